// SPDX-License-Identifier: MIT
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

#include <tutti/audio/offline_synth.hpp>

namespace tutti::audio {

struct OnsetOptions {
  int window_frames = 4096;       // analysis window (85 ms at 48 kHz: 11.7 Hz bins, so the
                                  // low notes' partials fall in bins of their own), a power of 2
  double leading_edge_s = 0.002;  // the window's fall at its newest end
  int bands_per_octave = 24;      // log-frequency bands (quarter tones): a step is a new band
  double compression = 1000.0;    // log(1 + compression * magnitude), full scale = 1
  int hop_frames = 48;            // 1 ms at 48 kHz: the time resolution
  double lag_s = 0.030;           // flux compares with the spectrum this long before
  double memory_s = 0.200;        // ... over its loudest since this long before
  double min_gap_s = 0.030;       // two onsets closer than this are one
  double threshold = 1.5;         // a peak must exceed the local mean by this much flux
  double local_window_s = 0.15;   // the local mean's span before the peak (and half after)
  double backtrack_s = 0.10;      // the rise's start is sought this far before the flux peak
  double power_fraction = 0.25;   // heard once the rising bands gain this share of their new
                                  // power (-6 dB): the perceptual onset of a slow attack
  double settle_s = 0.15;         // their new power: the most within this after the peak
  double silence_dbfs = -90.0;    // frames quieter than this add no flux
};

struct Onset {
  double time_s = 0.0;    // from the buffer's first frame
  double strength = 0.0;  // flux at the peak, relative to the loudest peak (0..1]
  double flux = 0.0;      // flux at the peak (summed log rises)
};

// The onset strength (spectral flux) of every hop-spaced frame, frame k stamped k * hop frames;
// empty for an empty buffer or bad options.
std::vector<double> onset_envelope(const AudioBuffer& audio, const OnsetOptions& options = {});

// The analysis window (oldest sample first), and the detector's step response: how long steady
// tones starting at t take to reach `power_fraction` of their power in it. The detector
// subtracts that, so an instant attack is placed at t.
std::vector<float> onset_window(const OnsetOptions& options, int sample_rate);
double onset_window_latency_s(const OnsetOptions& options, int sample_rate, double power_fraction);

// Onsets in time order. An empty or silent buffer has none.
std::vector<Onset> detect_onsets(const AudioBuffer& audio, const OnsetOptions& options = {});

}  // namespace tutti::audio
