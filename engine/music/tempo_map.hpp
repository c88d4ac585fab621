// SPDX-License-Identifier: MIT
#pragma once
// Ticks <-> seconds <-> beats for one score. A "beat" here is always a quarter note; metre-aware
// beats (dotted quarters in 6/8, ...) are computed by callers from the time signatures.
//
// Two timing modes, as in Standard MIDI Files:
//  - PPQ: `ticks_per_quarter` ticks per quarter note; tempo changes set the quarter's length.
//  - SMPTE: ticks are subdivisions of real-time frames; tempo changes then only affect beats.
// Everything is piecewise linear between tempo changes, so all conversions are exact inverses
// (up to floating point) and cost O(log changes).

#include <cstdint>
#include <vector>

namespace tutti::music {

struct TempoChange {
  std::int64_t tick = 0;
  double microseconds_per_quarter = 500000.0;  // 120 BPM
  // Derived, kept in sync by TempoMap: where this segment starts.
  double seconds = 0.0;
  double beats = 0.0;

  double bpm() const { return 60'000'000.0 / microseconds_per_quarter; }
};

class TempoMap {
 public:
  static constexpr double kDefaultMicrosecondsPerQuarter = 500000.0;

  // PPQ timing. Precondition: ticks_per_quarter > 0.
  static TempoMap with_ticks_per_quarter(int ticks_per_quarter);
  // SMPTE timing. frames_per_second is 24, 25, 29 (meaning 29.97 drop-frame) or 30.
  static TempoMap with_smpte(int frames_per_second, int ticks_per_frame);

  TempoMap() : TempoMap(with_ticks_per_quarter(480)) {}

  // Adds a tempo change (a later change at the same tick replaces the earlier one).
  // Precondition: microseconds_per_quarter > 0. Any tick order is accepted.
  void set_tempo(std::int64_t tick, double microseconds_per_quarter);

  double seconds_at(double tick) const;
  double beats_at(double tick) const;
  double ticks_at_seconds(double seconds) const;
  double ticks_at_beats(double beats) const;
  double seconds_at_beats(double beats) const { return seconds_at(ticks_at_beats(beats)); }
  double beats_at_seconds(double seconds) const { return beats_at(ticks_at_seconds(seconds)); }
  double bpm_at(double tick) const;

  bool is_smpte() const { return smpte_frames_per_second_ != 0; }
  int ticks_per_quarter() const { return ticks_per_quarter_; }  // 0 in SMPTE mode
  int smpte_frames_per_second() const { return smpte_frames_per_second_; }
  int smpte_ticks_per_frame() const { return smpte_ticks_per_frame_; }
  // Always at least one change, at tick 0.
  const std::vector<TempoChange>& changes() const { return changes_; }

 private:
  struct Empty {};
  explicit TempoMap(Empty) {}
  double seconds_per_tick(const TempoChange& change) const;
  double beats_per_tick(const TempoChange& change) const;
  void recompute();

  int ticks_per_quarter_ = 480;
  int smpte_frames_per_second_ = 0;
  int smpte_ticks_per_frame_ = 0;
  std::vector<TempoChange> changes_;
};

}  // namespace tutti::music
