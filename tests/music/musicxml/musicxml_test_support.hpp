// SPDX-License-Identifier: MIT
#pragma once
// Small builders for hand-written MusicXML in tests.

#include <cstdint>
#include <span>
#include <string>
#include <vector>

#include <tutti/music/musicxml/musicxml_reader.hpp>
#include <tutti/music/score.hpp>

namespace tutti::test {

inline std::span<const std::uint8_t> bytes_of(const std::string& text) {
  return {reinterpret_cast<const std::uint8_t*>(text.data()), text.size()};
}

inline Result<music::Score> read_xml(const std::string& xml,
                                     const std::string& name = "t.musicxml") {
  return music::read_musicxml(bytes_of(xml), name);
}

// A partwise score with one part "P1" holding `measures` (the <measure> elements).
inline std::string one_part_score(const std::string& measures,
                                  const std::string& score_part_extra = "") {
  return "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n"
         "<score-partwise version=\"4.0\">\n"
         "  <part-list><score-part id=\"P1\"><part-name>Piano</part-name>" +
         score_part_extra +
         "</score-part></part-list>\n"
         "  <part id=\"P1\">\n" +
         measures +
         "  </part>\n"
         "</score-partwise>\n";
}

inline std::string measure(const std::string& content, const std::string& number = "1") {
  return "    <measure number=\"" + number + "\">" + content + "</measure>\n";
}

inline std::string divisions(int value) {
  return "<attributes><divisions>" + std::to_string(value) + "</divisions></attributes>";
}

// <note> with a pitch; `before_duration` goes before <pitch> (grace, chord, cue), `after`
// after <duration> (tie, voice, staff, notations...).
inline std::string pitched(const std::string& step, int octave, int duration,
                           const std::string& after = "", const std::string& before = "",
                           const std::string& alter = "") {
  std::string note = "<note>" + before + "<pitch><step>" + step + "</step>";
  if (!alter.empty()) note += "<alter>" + alter + "</alter>";
  note += "<octave>" + std::to_string(octave) + "</octave></pitch>";
  if (duration >= 0) note += "<duration>" + std::to_string(duration) + "</duration>";
  return note + after + "</note>";
}

inline std::string grace(const std::string& step, int octave, const std::string& grace_attrs = "",
                         bool chord = false) {
  return pitched(step, octave, -1, "", "<grace" + grace_attrs + "/>" + (chord ? "<chord/>" : ""));
}

inline std::string rest(int duration) {
  return "<note><rest/><duration>" + std::to_string(duration) + "</duration></note>";
}

inline std::vector<music::Note> notes_of_part(const music::Score& score, int part) {
  std::vector<music::Note> notes;
  for (const music::Note& note : score.notes) {
    if (note.part == part) notes.push_back(note);
  }
  return notes;
}

}  // namespace tutti::test
