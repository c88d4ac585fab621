// SPDX-License-Identifier: MIT
#pragma once
// Where a sound starts, read the way a plain listener reads a waveform: the steepest rise of its
// short-time energy in decibels within a span, timed at the sample that enters the window. The
// spectral detector (onset_detection.hpp) finds the notes in a mix; a struck note (a hammer's)
// is heard where its energy jumps, a few milliseconds before the detector's -6 dB point, so the
// attack compensation and `tutti sync-report` place struck notes here, as an independent reading
// of the rendered WAV does (scripts/sync-energy-check).

#include <tutti/audio/offline_synth.hpp>

namespace tutti::audio {

struct EnergyRiseOptions {
  double window_s = 0.010;  // long enough that a sustained bass note's ripple is not a rise
  double hop_s = 0.00025;
  double floor_dbfs = -80.0;  // mean-square floor: silence makes no rises of its own
};

// Seconds from the buffer's first frame to the steepest energy rise within [from_s, to_s]
// (clamped to the buffer); `fallback_s` when the span holds no rise.
double steepest_energy_rise_s(const AudioBuffer& audio, double from_s, double to_s,
                              double fallback_s, const EnergyRiseOptions& options = {});

}  // namespace tutti::audio
