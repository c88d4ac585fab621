// SPDX-License-Identifier: MIT
#include <tutti/music/tempo_map.hpp>

#include <algorithm>
#include <iterator>

namespace tutti::music {

TempoMap TempoMap::with_ticks_per_quarter(int ticks_per_quarter) {
  TempoMap map{Empty{}};
  map.ticks_per_quarter_ = ticks_per_quarter > 0 ? ticks_per_quarter : 480;
  map.changes_.push_back(TempoChange{});
  return map;
}

TempoMap TempoMap::with_smpte(int frames_per_second, int ticks_per_frame) {
  TempoMap map{Empty{}};
  map.ticks_per_quarter_ = 0;
  map.smpte_frames_per_second_ = frames_per_second > 0 ? frames_per_second : 30;
  map.smpte_ticks_per_frame_ = ticks_per_frame > 0 ? ticks_per_frame : 1;
  map.changes_.push_back(TempoChange{});
  return map;
}

void TempoMap::set_tempo(std::int64_t tick, double microseconds_per_quarter) {
  if (!(microseconds_per_quarter > 0.0)) return;
  tick = std::max<std::int64_t>(tick, 0);
  // Readers add changes in time order: appending then costs O(1), not a full recompute.
  if (tick > changes_.back().tick) {
    const TempoChange& prev = changes_.back();
    const double span = static_cast<double>(tick - prev.tick);
    TempoChange change;
    change.tick = tick;
    change.microseconds_per_quarter = microseconds_per_quarter;
    change.seconds = prev.seconds + span * seconds_per_tick(prev);
    change.beats = prev.beats + span * beats_per_tick(prev);
    changes_.push_back(change);
    return;
  }
  auto at = std::lower_bound(changes_.begin(), changes_.end(), tick,
                             [](const TempoChange& c, std::int64_t t) { return c.tick < t; });
  if (at != changes_.end() && at->tick == tick) {
    at->microseconds_per_quarter = microseconds_per_quarter;
  } else {
    TempoChange change;
    change.tick = tick;
    change.microseconds_per_quarter = microseconds_per_quarter;
    changes_.insert(at, change);
  }
  recompute();
}

double TempoMap::seconds_per_tick(const TempoChange& change) const {
  if (is_smpte()) {
    const double fps = smpte_frames_per_second_ == 29 ? 29.97 : smpte_frames_per_second_;
    return 1.0 / (fps * smpte_ticks_per_frame_);
  }
  return change.microseconds_per_quarter / 1e6 / ticks_per_quarter_;
}

double TempoMap::beats_per_tick(const TempoChange& change) const {
  if (is_smpte()) return seconds_per_tick(change) * 1e6 / change.microseconds_per_quarter;
  return 1.0 / ticks_per_quarter_;
}

void TempoMap::recompute() {
  for (std::size_t i = 1; i < changes_.size(); ++i) {
    const TempoChange& prev = changes_[i - 1];
    const double span = static_cast<double>(changes_[i].tick - prev.tick);
    changes_[i].seconds = prev.seconds + span * seconds_per_tick(prev);
    changes_[i].beats = prev.beats + span * beats_per_tick(prev);
  }
}

namespace {
// The segment containing `value` according to `key`; the first segment extends to -infinity.
template <typename Key>
std::size_t segment_for(const std::vector<TempoChange>& changes, double value, Key key) {
  auto after = std::upper_bound(changes.begin() + 1, changes.end(), value,
                                [&](double v, const TempoChange& c) { return v < key(c); });
  return static_cast<std::size_t>(std::distance(changes.begin(), after)) - 1;
}
}  // namespace

double TempoMap::seconds_at(double tick) const {
  const auto& c = changes_[segment_for(
      changes_, tick, [](const TempoChange& t) { return static_cast<double>(t.tick); })];
  return c.seconds + (tick - static_cast<double>(c.tick)) * seconds_per_tick(c);
}

double TempoMap::beats_at(double tick) const {
  const auto& c = changes_[segment_for(
      changes_, tick, [](const TempoChange& t) { return static_cast<double>(t.tick); })];
  return c.beats + (tick - static_cast<double>(c.tick)) * beats_per_tick(c);
}

double TempoMap::ticks_at_seconds(double seconds) const {
  const auto& c =
      changes_[segment_for(changes_, seconds, [](const TempoChange& t) { return t.seconds; })];
  return static_cast<double>(c.tick) + (seconds - c.seconds) / seconds_per_tick(c);
}

double TempoMap::ticks_at_beats(double beats) const {
  const auto& c =
      changes_[segment_for(changes_, beats, [](const TempoChange& t) { return t.beats; })];
  return static_cast<double>(c.tick) + (beats - c.beats) / beats_per_tick(c);
}

double TempoMap::bpm_at(double tick) const {
  return changes_[segment_for(changes_, tick,
                              [](const TempoChange& t) { return static_cast<double>(t.tick); })]
      .bpm();
}

}  // namespace tutti::music
