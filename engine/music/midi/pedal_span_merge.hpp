// SPDX-License-Identifier: MIT
#pragma once
// Sustain pedal spans as MIDI can express them: per part, no two spans overlap (a second
// "pedal down" while the pedal is down means nothing) and none is empty. Spans that merely touch
// are kept apart, because lifting and re-pressing the pedal at one instant is a real pedal change
// that clears the held sound.

#include <algorithm>
#include <tuple>
#include <vector>

#include <tutti/music/score.hpp>

namespace tutti::music::midi_detail {

inline std::vector<PedalSpan> merge_overlapping_pedal_spans(std::vector<PedalSpan> spans) {
  std::erase_if(spans, [](const PedalSpan& s) { return s.offset_ticks <= s.onset_ticks; });
  std::sort(spans.begin(), spans.end(), [](const PedalSpan& a, const PedalSpan& b) {
    return std::tie(a.part, a.onset_ticks, a.offset_ticks) <
           std::tie(b.part, b.onset_ticks, b.offset_ticks);
  });
  std::vector<PedalSpan> merged;
  for (const PedalSpan& span : spans) {
    if (!merged.empty() && merged.back().part == span.part &&
        span.onset_ticks < merged.back().offset_ticks) {
      merged.back().offset_ticks = std::max(merged.back().offset_ticks, span.offset_ticks);
    } else {
      merged.push_back(span);
    }
  }
  return merged;
}

}  // namespace tutti::music::midi_detail
