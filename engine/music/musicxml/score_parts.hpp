// SPDX-License-Identifier: MIT
#pragma once
// The parts of a MusicXML score: what <part-list> says about each (name, MIDI program and
// channel, percussion keys) and which elements hold its measures. Partwise and timewise scores
// come out the same way, so the measure walk does not care which one the file is.

#include <cstddef>
#include <pugixml.hpp>
#include <string>
#include <utility>
#include <vector>

namespace tutti::music::musicxml {

struct PartInfo {
  std::string id;
  std::string name;
  int program = 0;   // 0-based General MIDI program (MusicXML counts from 1)
  int channel = -1;  // 0-based MIDI channel, -1 = not stated
  // <midi-unpitched> keys (0-based) by score-instrument id, for percussion notes.
  std::vector<std::pair<std::string, int>> unpitched_keys;
};

// One measure of one part. `measure` carries the number attribute; `content` holds the notes:
// the <measure> itself in a partwise score, the <part> inside it in a timewise score. `index`
// is the measure's position in the score (0-based), which lines parts up; a timewise measure
// that leaves a part out simply has no slot in that part, so memory stays proportional to the
// elements in the file.
struct MeasureSlot {
  pugi::xml_node measure;
  pugi::xml_node content;
  std::size_t index = 0;
};

struct PartLayout {
  PartInfo info;
  std::vector<MeasureSlot> measures;
};

// Parts in the order of the <part> elements (partwise) or of <part-list> (timewise). A <part>
// whose id is missing or unknown takes the <score-part> at the same position.
std::vector<PartLayout> layout_parts(pugi::xml_node root);

// The 0-based <midi-unpitched> key for a note's <instrument id>, or the part's first one; -1 if
// the part states none.
int unpitched_key(const PartInfo& part, const char* instrument_id);

}  // namespace tutti::music::musicxml
