#pragma once
// Note onsets found in audio alone, with no knowledge of the score: a spectral-flux onset
// detector (log-magnitude spectra, the rise of each bin over the maximum of its neighbours a few
// milliseconds earlier, as in Böck & Widmer's SuperFlux) with an adaptive threshold, and each
// onset placed at the start of its rise rather than at the flux peak. It is what
// `tutti sync-report` holds the animation against, so it must not read the plans.
//
// Time convention: an analysis frame is stamped with its newest sample (the window's leading
// edge), so a sound starting at t begins to raise the flux at t, not half a window earlier.

#include <vector>

#include "audio/offline_synth.hpp"

namespace tutti::audio {

struct OnsetOptions {
  int window_frames = 2048;       // analysis window (42.7 ms at 48 kHz), a power of two
  double leading_edge_s = 0.002;  // the window's fall at its newest end
  int bands_per_octave = 24;      // log-frequency bands (quarter tones): a step is a new band
  double compression = 1000.0;    // log(1 + compression * magnitude), full scale = 1
  int hop_frames = 48;            // 1 ms at 48 kHz: the time resolution
  double lag_s = 0.005;           // flux compares with the spectrum this long before
  double min_gap_s = 0.030;       // two onsets closer than this are one
  double threshold = 0.12;        // a peak must exceed the local mean by this share of the
                                  // loudest peak in the file
  double local_window_s = 0.15;   // the local mean's span before the peak (and half after)
  double rise_fraction = 0.1;     // the onset is where the flux first reaches this share of
                                  // its peak (above the level before the rise)
  double silence_dbfs = -90.0;    // frames quieter than this add no flux
};

struct Onset {
  double time_s = 0.0;    // from the buffer's first frame
  double strength = 0.0;  // flux at the peak, relative to the loudest peak (0..1]
};

// The onset strength (spectral flux) of every hop-spaced frame, frame k stamped k * hop frames;
// empty for an empty buffer or bad options.
std::vector<double> onset_envelope(const AudioBuffer& audio, const OnsetOptions& options = {});

// Onsets in time order. An empty or silent buffer has none.
std::vector<Onset> detect_onsets(const AudioBuffer& audio, const OnsetOptions& options = {});

}  // namespace tutti::audio
