// SPDX-License-Identifier: MIT
#include <tutti/music/musicxml/musicxml_reader.hpp>

#include <gtest/gtest.h>

#include <chrono>
#include <string>
#include <vector>

#include <tutti/music/musicxml/fingering_text.hpp>
#include <tutti/music/musicxml/mxl_archive.hpp>
#include <tutti/music/musicxml/tick_resolution.hpp>
#include "musicxml_test_support.hpp"
#include "zip_builder.hpp"

namespace tutti::music {
namespace {

using test::divisions;
using test::grace;
using test::measure;
using test::notes_of_part;
using test::one_part_score;
using test::pitched;
using test::read_xml;
using test::rest;

// ppq is lcm(480, divisions): with divisions 1 a quarter is 480 ticks.
constexpr std::int64_t kQ = 480;

TEST(MusicXmlReaderTest, ChordNotesShareTheOnsetAndTheCursorFollowsTheFirstNote) {
  const auto score = read_xml(one_part_score(
      measure(divisions(1) + pitched("C", 4, 2) + pitched("E", 4, 1, "", "<chord/>") +
              pitched("G", 4, 2, "", "<chord/>") + pitched("D", 4, 1))));
  ASSERT_TRUE(score.ok()) << score.error().message;
  ASSERT_EQ(score->notes.size(), 4u);
  EXPECT_EQ(score->tempo_map.ticks_per_quarter(), 480);
  const Note& c = score->notes[0];
  const Note& e = score->notes[1];
  const Note& g = score->notes[2];
  const Note& d = score->notes[3];
  EXPECT_EQ(c.pitch, 60);
  EXPECT_EQ(e.pitch, 64);
  EXPECT_EQ(g.pitch, 67);
  EXPECT_EQ(c.onset_ticks, 0);
  EXPECT_EQ(e.onset_ticks, 0);
  EXPECT_EQ(g.onset_ticks, 0);
  EXPECT_EQ(e.offset_ticks, kQ);  // chord notes keep their own durations
  EXPECT_EQ(g.offset_ticks, 2 * kQ);
  EXPECT_EQ(d.pitch, 62);
  EXPECT_EQ(d.onset_ticks, 2 * kQ);  // after the first chord note's duration
  EXPECT_EQ(score->end_ticks, 3 * kQ);
  EXPECT_DOUBLE_EQ(d.onset_s, 1.0);  // 120 bpm by default
}

TEST(MusicXmlReaderTest, BackupAndForwardMoveTheCursor) {
  const auto score =
      read_xml(one_part_score(measure(divisions(2) + pitched("C", 5, 8, "<voice>1</voice>") +
                                      "<backup><duration>8</duration></backup>" +
                                      "<forward><duration>4</duration></forward>" +
                                      pitched("C", 3, 4, "<voice>2</voice>")) +
                              measure(pitched("D", 5, 8, "<voice>1</voice>"), "2")));
  ASSERT_TRUE(score.ok()) << score.error().message;
  ASSERT_EQ(score->notes.size(), 3u);
  EXPECT_EQ(score->notes[0].pitch, 72);
  EXPECT_EQ(score->notes[0].voice, 1);
  EXPECT_EQ(score->notes[1].pitch, 48);
  EXPECT_EQ(score->notes[1].voice, 2);
  EXPECT_EQ(score->notes[1].onset_ticks, 2 * kQ);
  EXPECT_EQ(score->notes[1].offset_ticks, 4 * kQ);
  EXPECT_EQ(score->notes[2].onset_ticks, 4 * kQ);
  EXPECT_EQ(score->end_ticks, 8 * kQ);
}

TEST(MusicXmlReaderTest, BackupPastTheMeasureStartStopsThere) {
  // Exporters do this (the test suite's 11b backs up 384 in a measure of 4).
  const auto score = read_xml(
      one_part_score(measure(pitched("C", 5, 4) + "<backup><duration>400</duration></backup>" +
                             pitched("C", 3, 4, "<voice>2</voice>"))));
  ASSERT_TRUE(score.ok()) << score.error().message;
  ASSERT_EQ(score->notes.size(), 2u);
  EXPECT_EQ(score->notes[0].onset_ticks, 0);
  EXPECT_EQ(score->notes[1].onset_ticks, 0);
}

TEST(MusicXmlReaderTest, DivisionChangesKeepTicksExact) {
  // divisions 1, then 7 (septuplets), then 3: ppq = lcm(480, 7, 3) = 3360.
  const auto score =
      read_xml(one_part_score(measure(divisions(1) + pitched("C", 4, 1) + divisions(7) +
                                      pitched("D", 4, 1) + pitched("E", 4, 6)) +
                              measure(divisions(3) + pitched("F", 4, 1), "2")));
  ASSERT_TRUE(score.ok()) << score.error().message;
  ASSERT_EQ(score->tempo_map.ticks_per_quarter(), 3360);
  ASSERT_EQ(score->notes.size(), 4u);
  EXPECT_EQ(score->notes[1].onset_ticks, 3360);
  EXPECT_EQ(score->notes[1].offset_ticks, 3360 + 480);
  EXPECT_EQ(score->notes[2].offset_ticks, 2 * 3360);
  EXPECT_EQ(score->notes[3].onset_ticks, 2 * 3360);
  EXPECT_EQ(score->notes[3].offset_ticks, 2 * 3360 + 1120);
}

TEST(MusicXmlReaderTest, DivisionsBeyondTheCapFallBackToAFixedResolution) {
  // 999983 is prime: lcm(480, 999983) is far above the cap, so ticks are rounded.
  const auto score = read_xml(one_part_score(
      measure(divisions(999983) + pitched("C", 4, 999983) + pitched("D", 4, 333328))));
  ASSERT_TRUE(score.ok()) << score.error().message;
  EXPECT_EQ(score->tempo_map.ticks_per_quarter(), musicxml::kFallbackTicksPerQuarter);
  ASSERT_EQ(score->notes.size(), 2u);
  EXPECT_EQ(score->notes[1].onset_ticks, 665280);
  EXPECT_EQ(score->notes[1].offset_ticks - score->notes[1].onset_ticks, 221760);  // ~1/3
}

TEST(MusicXmlReaderTest, TieChainsMergeIntoOneNoteKeepingTheFirstElement) {
  const std::string start = "<tie type=\"start\"/>";
  const std::string stop = "<tie type=\"stop\"/>";
  const auto score = read_xml(one_part_score(
      measure(divisions(1) + rest(2) + pitched("C", 4, 2, start) +
              pitched("E", 4, 2, start, "<chord/>")) +
      measure(pitched("C", 4, 4, stop + start) + pitched("E", 4, 4, stop, "<chord/>"), "2") +
      measure(pitched("C", 4, 1, stop) + pitched("C", 4, 1), "3")));
  ASSERT_TRUE(score.ok()) << score.error().message;
  ASSERT_EQ(score->notes.size(), 3u);
  const Note& c = score->notes[0];
  const Note& e = score->notes[1];
  EXPECT_EQ(c.pitch, 60);
  EXPECT_EQ(c.onset_ticks, 2 * kQ);
  EXPECT_EQ(c.offset_ticks, 9 * kQ);  // 2 + 4 + 1 quarters
  EXPECT_EQ(c.source_index, 1);       // the rest is <note> #0
  EXPECT_EQ(e.pitch, 64);
  EXPECT_EQ(e.offset_ticks, 8 * kQ);
  EXPECT_EQ(e.source_index, 2);
  EXPECT_EQ(score->notes[2].onset_ticks, 9 * kQ);  // a new attack of the same pitch
}

TEST(MusicXmlReaderTest, TiesSurviveVoicesInterleavedByBackup) {
  const auto score = read_xml(one_part_score(
      measure(divisions(1) + pitched("G", 4, 4, "<tie type=\"start\"/><voice>1</voice>") +
              "<backup><duration>4</duration></backup>" + pitched("G", 4, 4, "<voice>2</voice>")) +
      measure(pitched("G", 4, 4, "<tie type=\"stop\"/><voice>1</voice>"), "2")));
  ASSERT_TRUE(score.ok()) << score.error().message;
  ASSERT_EQ(score->notes.size(), 2u);
  const auto voice1 = score->notes[0].voice == 1 ? score->notes[0] : score->notes[1];
  EXPECT_EQ(voice1.offset_ticks, 8 * kQ);
}

TEST(MusicXmlReaderTest, TiedNotationWithoutTieElementStillTies) {
  const auto score = read_xml(one_part_score(
      measure(divisions(1) + pitched("C", 4, 2, "<notations><tied type=\"start\"/></notations>") +
              pitched("C", 4, 2, "<notations><tied type=\"stop\"/></notations>"))));
  ASSERT_TRUE(score.ok()) << score.error().message;
  ASSERT_EQ(score->notes.size(), 1u);
  EXPECT_EQ(score->notes[0].offset_ticks, 4 * kQ);
}

TEST(MusicXmlReaderTest, GraceNotesSoundOnTheBeatAndDelayThePrincipal) {
  const auto score =
      read_xml(one_part_score(measure(divisions(1) + pitched("E", 4, 1) + grace("D", 5) +
                                      grace("E", 5) + grace("G", 5, "", /*chord=*/true) +
                                      pitched("C", 5, 1) + pitched("F", 5, 1, "", "<chord/>"))));
  ASSERT_TRUE(score.ok()) << score.error().message;
  ASSERT_EQ(score->notes.size(), 6u);
  // Two grace slots (the E5+G5 grace chord is one), a 32nd (60 ticks) each, from the beat.
  const auto& n = score->notes;
  EXPECT_EQ(n[0].pitch, 64);
  EXPECT_EQ(n[0].offset_ticks, kQ);
  EXPECT_EQ(n[1].pitch, 74);
  EXPECT_TRUE(n[1].grace);
  EXPECT_EQ(n[1].onset_ticks, kQ);
  EXPECT_EQ(n[1].offset_ticks, kQ + 60);
  EXPECT_EQ(n[1].source_index, 1);
  EXPECT_EQ(n[2].pitch, 76);
  EXPECT_EQ(n[3].pitch, 79);
  EXPECT_EQ(n[2].onset_ticks, kQ + 60);
  EXPECT_EQ(n[3].onset_ticks, kQ + 60);
  EXPECT_EQ(n[3].offset_ticks, kQ + 120);
  // The principal chord starts after the graces and keeps its end.
  EXPECT_EQ(n[4].pitch, 72);
  EXPECT_EQ(n[5].pitch, 77);
  EXPECT_FALSE(n[4].grace);
  EXPECT_EQ(n[4].onset_ticks, kQ + 120);
  EXPECT_EQ(n[5].onset_ticks, kQ + 120);
  EXPECT_EQ(n[4].offset_ticks, 2 * kQ);
  EXPECT_EQ(score->end_ticks, 2 * kQ);
}

TEST(MusicXmlReaderTest, GraceNotesNeverTakeMoreThanHalfThePrincipal) {
  // Eight graces before a 16th (120 ticks): they share 60 ticks.
  std::string graces;
  for (int i = 0; i < 8; ++i) graces += grace("D", 5);
  const auto score = read_xml(one_part_score(measure(divisions(4) + graces + pitched("C", 5, 1))));
  ASSERT_TRUE(score.ok()) << score.error().message;
  ASSERT_EQ(score->notes.size(), 9u);
  for (const Note& note : score->notes) EXPECT_GE(note.offset_ticks, note.onset_ticks);
  EXPECT_EQ(score->notes.back().onset_ticks, 60);
  EXPECT_EQ(score->notes.back().offset_ticks, 120);
}

TEST(MusicXmlReaderTest, AfterGracesEndThePreviousNote) {
  const auto score = read_xml(one_part_score(
      measure(divisions(1) + pitched("C", 5, 2) + grace("D", 5, " steal-time-previous=\"25\"") +
              pitched("E", 5, 1) + pitched("F", 5, 1) + grace("G", 5))));
  ASSERT_TRUE(score.ok()) << score.error().message;
  ASSERT_EQ(score->notes.size(), 5u);
  const auto& n = score->notes;
  // 25% of the C5 (960 ticks) = 240: the after-grace takes the C5's tail.
  EXPECT_EQ(n[0].pitch, 72);
  EXPECT_EQ(n[0].offset_ticks, 720);
  EXPECT_EQ(n[1].pitch, 74);
  EXPECT_EQ(n[1].onset_ticks, 720);
  EXPECT_EQ(n[1].offset_ticks, 960);
  EXPECT_EQ(n[2].onset_ticks, 960);  // the E5 is not delayed
  // A grace with nothing after it ends the part's last note.
  EXPECT_EQ(n[3].pitch, 77);
  EXPECT_EQ(n[3].offset_ticks, 4 * kQ - 60);
  EXPECT_EQ(n[4].pitch, 79);
  EXPECT_EQ(n[4].onset_ticks, 4 * kQ - 60);
  EXPECT_EQ(n[4].offset_ticks, 4 * kQ);
}

TEST(MusicXmlReaderTest, TempoFromSoundAnywhereDirectionOffsetsAndMetronome) {
  const auto score = read_xml(one_part_score(
      measure(divisions(2) + "<sound tempo=\"60\"/>" + pitched("C", 4, 4) +
              "<direction><direction-type><words>rit.</words></direction-type>"
              "<offset sound=\"yes\">2</offset><sound tempo=\"90\"/></direction>" +
              pitched("D", 4, 4)) +
      measure("<direction><direction-type><metronome><beat-unit>half</beat-unit>"
              "<per-minute>40</per-minute></metronome></direction-type></direction>" +
                  pitched("E", 4, 8),
              "2")));
  ASSERT_TRUE(score.ok()) << score.error().message;
  const auto& changes = score->tempo_map.changes();
  ASSERT_EQ(changes.size(), 3u);
  EXPECT_EQ(changes[0].tick, 0);
  EXPECT_DOUBLE_EQ(changes[0].bpm(), 60.0);
  EXPECT_EQ(changes[1].tick, 3 * kQ);  // the direction at beat 2, offset by a quarter
  EXPECT_DOUBLE_EQ(changes[1].bpm(), 90.0);
  EXPECT_EQ(changes[2].tick, 4 * kQ);
  EXPECT_DOUBLE_EQ(changes[2].bpm(), 80.0);  // half = 40 -> 80 quarters a minute
  EXPECT_DOUBLE_EQ(score->notes[1].onset_s, 2.0);
}

TEST(MusicXmlReaderTest, TempoRepeatedByEveryPartIsOneChange) {
  const std::string part_measures =
      measure(divisions(1) + "<sound tempo=\"100\"/>" + pitched("C", 4, 4)) +
      measure("<sound tempo=\"100\"/>" + pitched("C", 4, 4), "2");
  const std::string xml =
      "<score-partwise><part-list><score-part id=\"A\"/><score-part id=\"B\"/></part-list>"
      "<part id=\"A\">" +
      part_measures + "</part><part id=\"B\">" + part_measures + "</part></score-partwise>";
  const auto score = read_xml(xml);
  ASSERT_TRUE(score.ok()) << score.error().message;
  ASSERT_EQ(score->tempo_map.changes().size(), 1u);
  EXPECT_DOUBLE_EQ(score->tempo_map.changes()[0].bpm(), 100.0);
}

TEST(MusicXmlReaderTest, TransposingPartsSoundTransposed) {
  // Bass clarinet in Bb: written D5 sounds a major ninth lower, C4. Written E major (4 sharps)
  // is concert D major (2 sharps).
  const auto score = read_xml(
      one_part_score(measure("<attributes><divisions>1</divisions><key><fifths>4</fifths></key>"
                             "<transpose><diatonic>-1</diatonic><chromatic>-2</chromatic>"
                             "<octave-change>-1</octave-change></transpose></attributes>" +
                             pitched("D", 5, 4))));
  ASSERT_TRUE(score.ok()) << score.error().message;
  EXPECT_EQ(score->parts[0].transpose_semitones, -14);
  ASSERT_EQ(score->notes.size(), 1u);
  EXPECT_EQ(score->notes[0].pitch, 60);
  ASSERT_EQ(score->key_signatures.size(), 1u);
  EXPECT_EQ(score->key_signatures[0].fifths, 2);
}

TEST(MusicXmlReaderTest, StavesAndStaffNumbers) {
  const auto score = read_xml(
      one_part_score(measure("<attributes><divisions>1</divisions><staves>2</staves></attributes>" +
                             pitched("C", 5, 4, "<voice>1</voice><staff>1</staff>") +
                             "<backup><duration>4</duration></backup>" +
                             pitched("C", 3, 4, "<voice>5</voice><staff>2</staff>"))));
  ASSERT_TRUE(score.ok()) << score.error().message;
  EXPECT_EQ(score->parts[0].staves, 2);
  ASSERT_EQ(score->notes.size(), 2u);
  EXPECT_EQ(score->notes[0].staff, 2);
  EXPECT_EQ(score->notes[0].voice, 5);
  EXPECT_EQ(score->notes[1].staff, 1);
}

std::string fingered(const std::string& step, const std::string& fingerings) {
  return pitched(step, 4, 1, "<notations><technical>" + fingerings + "</technical></notations>");
}

TEST(MusicXmlReaderTest, FingeringMarksBecomeFingers) {
  const auto score = read_xml(one_part_score(measure(
      divisions(1) + fingered("C", "<fingering>3</fingering>") +
      fingered("D", "<fingering>3-1</fingering>") + fingered("E", "<fingering> 4 2 </fingering>") +
      fingered("F", "<fingering>2</fingering><fingering substitution=\"yes\">5</fingering>") +
      fingered("G", "<fingering>p</fingering>") + fingered("A", "<fingering>7</fingering>") +
      fingered("B", "<fingering alternate=\"yes\">4</fingering><fingering>1</fingering>") +
      pitched("C", 5, 1))));
  ASSERT_TRUE(score.ok()) << score.error().message;
  ASSERT_EQ(score->notes.size(), 8u);
  const auto& n = score->notes;
  EXPECT_EQ(n[0].finger, 3);
  EXPECT_EQ(n[0].finger_substitute, 0);
  EXPECT_EQ(n[1].finger, 3);
  EXPECT_EQ(n[1].finger_substitute, 1);
  EXPECT_EQ(n[2].finger, 4);
  EXPECT_EQ(n[2].finger_substitute, 2);
  EXPECT_EQ(n[3].finger, 2);
  EXPECT_EQ(n[3].finger_substitute, 5);
  EXPECT_EQ(n[4].finger, 0);  // guitar-style letter: not a piano finger
  EXPECT_EQ(n[5].finger, 0);
  EXPECT_EQ(n[6].finger, 1);  // the alternate fingering is not the one played
  EXPECT_EQ(n[7].finger, 0);
}

TEST(MusicXmlReaderTest, FingeringTextParsing) {
  using musicxml::parse_fingering_text;
  EXPECT_EQ(parse_fingering_text("5")->finger, 5);
  EXPECT_EQ(parse_fingering_text("3\xE2\x80\x93"
                                 "1")
                ->substitute,
            1);  // en dash
  EXPECT_EQ(parse_fingering_text("31")->substitute, 1);
  EXPECT_FALSE(parse_fingering_text("").has_value());
  EXPECT_FALSE(parse_fingering_text("0").has_value());
  EXPECT_FALSE(parse_fingering_text("T").has_value());
}

TEST(MusicXmlReaderTest, PartListGivesNamesProgramsAndChannels) {
  const std::string measures = measure(divisions(1) + pitched("C", 4, 4));
  const std::string xml =
      "<score-partwise><part-list>"
      "<score-part id=\"Tpt\"><part-name>Trumpet in Bb</part-name>"
      "<score-instrument id=\"Tpt-I1\"><instrument-name>Trumpet</instrument-name>"
      "</score-instrument><midi-instrument id=\"Tpt-I1\"><midi-channel>3</midi-channel>"
      "<midi-program>57</midi-program></midi-instrument></score-part>"
      "<score-part id=\"Pno\"><part-name>Piano</part-name></score-part>"
      "</part-list><part id=\"Tpt\">" +
      measures + "</part><part id=\"Pno\">" + measures + "</part></score-partwise>";
  const auto score = read_xml(xml);
  ASSERT_TRUE(score.ok()) << score.error().message;
  ASSERT_EQ(score->parts.size(), 2u);
  EXPECT_EQ(score->parts[0].id, "Tpt");
  EXPECT_EQ(score->parts[0].name, "Trumpet in Bb");
  EXPECT_EQ(score->parts[0].program, 56);
  EXPECT_EQ(score->parts[0].channel, 2);
  EXPECT_EQ(score->parts[1].name, "Piano");
  EXPECT_EQ(score->parts[1].channel, -1);
  ASSERT_EQ(score->notes.size(), 2u);
  for (const Note& note : score->notes) EXPECT_EQ(note.channel, note.part == 0 ? 2 : 1);
}

TEST(MusicXmlReaderTest, TimeAndKeySignatures) {
  const auto score = read_xml(one_part_score(
      measure("<attributes><divisions>2</divisions><key><fifths>-3</fifths><mode>minor</mode>"
              "</key><time><beats>3+2</beats><beat-type>8</beat-type></time></attributes>" +
              pitched("C", 4, 5)) +
      measure("<attributes><time><beats>2</beats><beat-type>4</beat-type><beats>3</beats>"
              "<beat-type>8</beat-type></time></attributes>" +
                  pitched("C", 4, 7),
              "2") +
      measure("<attributes><time><senza-misura/></time></attributes>" + pitched("C", 4, 1), "3")));
  ASSERT_TRUE(score.ok()) << score.error().message;
  ASSERT_EQ(score->time_signatures.size(), 2u);
  EXPECT_EQ(score->time_signatures[0].numerator, 5);
  EXPECT_EQ(score->time_signatures[0].denominator, 8);
  EXPECT_EQ(score->time_signatures[1].tick, 5 * kQ / 2);
  EXPECT_EQ(score->time_signatures[1].numerator, 7);
  EXPECT_EQ(score->time_signatures[1].denominator, 8);
  ASSERT_EQ(score->key_signatures.size(), 1u);
  EXPECT_EQ(score->key_signatures[0].fifths, -3);
  EXPECT_TRUE(score->key_signatures[0].minor);
}

TEST(MusicXmlReaderTest, SustainPedalMarksBecomeSpans) {
  auto pedal = [](const std::string& type) {
    return "<direction><direction-type><pedal type=\"" + type +
           "\"/></direction-type><sound damper-pedal=\"" + (type == "stop" ? "no" : "yes") +
           "\"/></direction>";
  };
  const auto score = read_xml(
      one_part_score(measure(divisions(1) + pedal("start") + pitched("C", 4, 2) + pedal("change") +
                             pitched("D", 4, 2)) +
                     measure(pedal("stop") + pitched("E", 4, 2) +
                                 "<direction><direction-type><words>Ped.</words></direction-type>"
                                 "<sound damper-pedal=\"yes\"/></direction>" +
                                 pitched("F", 4, 2),
                             "2")));
  ASSERT_TRUE(score.ok()) << score.error().message;
  ASSERT_EQ(score->pedal_spans.size(), 3u);
  EXPECT_EQ(score->pedal_spans[0].onset_ticks, 0);
  EXPECT_EQ(score->pedal_spans[0].offset_ticks, 2 * kQ);
  EXPECT_EQ(score->pedal_spans[1].onset_ticks, 2 * kQ);
  EXPECT_EQ(score->pedal_spans[1].offset_ticks, 4 * kQ);
  // Still down at the end: lifted at the end of the part.
  EXPECT_EQ(score->pedal_spans[2].onset_ticks, 6 * kQ);
  EXPECT_EQ(score->pedal_spans[2].offset_ticks, 8 * kQ);
}

TEST(MusicXmlReaderTest, DynamicsSetVelocities) {
  const auto score = read_xml(one_part_score(
      measure(divisions(1) + pitched("C", 4, 1) + "<sound dynamics=\"100\"/>" + pitched("D", 4, 1) +
              "<direction><direction-type><dynamics><pp/></dynamics></direction-type></direction>" +
              pitched("E", 4, 1) +
              "<note dynamics=\"50\"><pitch><step>F</step><octave>4</octave>"
              "</pitch><duration>1</duration></note>")));
  ASSERT_TRUE(score.ok()) << score.error().message;
  ASSERT_EQ(score->notes.size(), 4u);
  EXPECT_EQ(score->notes[0].velocity, 80);  // nothing stated
  EXPECT_EQ(score->notes[1].velocity, 90);  // 100% of forte 90
  EXPECT_EQ(score->notes[2].velocity, 33);  // pp
  EXPECT_EQ(score->notes[3].velocity, 45);
}

TEST(MusicXmlReaderTest, CueNotesTakeTimeButDoNotSound) {
  const auto score = read_xml(one_part_score(
      measure(divisions(1) + pitched("C", 4, 2, "", "<cue/>") + pitched("D", 4, 2))));
  ASSERT_TRUE(score.ok()) << score.error().message;
  ASSERT_EQ(score->notes.size(), 1u);
  EXPECT_EQ(score->notes[0].pitch, 62);
  EXPECT_EQ(score->notes[0].onset_ticks, 2 * kQ);
  EXPECT_EQ(score->notes[0].source_index, 1);
}

TEST(MusicXmlReaderTest, UnpitchedNotesUseMidiUnpitchedOrDisplayPitch) {
  const std::string instrument =
      "<score-instrument id=\"P1-X1\"><instrument-name>Snare</instrument-name>"
      "</score-instrument><score-instrument id=\"P1-X2\"><instrument-name>Hat</instrument-name>"
      "</score-instrument><midi-instrument id=\"P1-X1\"><midi-unpitched>39</midi-unpitched>"
      "</midi-instrument><midi-instrument id=\"P1-X2\"><midi-unpitched>43</midi-unpitched>"
      "</midi-instrument>";
  auto drum = [](const std::string& id) {
    return "<note><unpitched><display-step>C</display-step><display-octave>5</display-octave>"
           "</unpitched><duration>1</duration><instrument id=\"" +
           id + "\"/></note>";
  };
  const auto score =
      read_xml(one_part_score(measure(divisions(1) + drum("P1-X1") + drum("P1-X2")), instrument));
  ASSERT_TRUE(score.ok()) << score.error().message;
  EXPECT_TRUE(score->parts[0].percussion);
  ASSERT_EQ(score->notes.size(), 2u);
  EXPECT_EQ(score->notes[0].pitch, 38);  // acoustic snare
  EXPECT_EQ(score->notes[1].pitch, 42);  // closed hi-hat
  EXPECT_EQ(score->notes[0].channel, 9);

  const auto plain = read_xml(one_part_score(measure(divisions(1) + drum("none"))));
  ASSERT_TRUE(plain.ok()) << plain.error().message;
  ASSERT_EQ(plain->notes.size(), 1u);
  EXPECT_EQ(plain->notes[0].pitch, 72);  // the display position, C5
}

TEST(MusicXmlReaderTest, MicrotonesRoundToTheNearestSemitone) {
  const auto score = read_xml(one_part_score(
      measure(divisions(1) + pitched("D", 4, 1, "", "", "-0.5") +
              pitched("D", 4, 1, "", "", "1.5") + pitched("D", 4, 1, "", "", "0.25"))));
  ASSERT_TRUE(score.ok()) << score.error().message;
  ASSERT_EQ(score->notes.size(), 3u);
  EXPECT_EQ(score->notes[0].pitch, 61);
  EXPECT_EQ(score->notes[1].pitch, 64);
  EXPECT_EQ(score->notes[2].pitch, 62);
}

TEST(MusicXmlReaderTest, MeasuresAlignAcrossPartsAndPickupsAreNotPadded) {
  // Part A leaves measure 1 empty; measure 2 still starts after part B's measure 1. The
  // one-beat pickup lasts one beat whatever the time signature says.
  const std::string xml =
      "<score-partwise><part-list><score-part id=\"A\"/><score-part id=\"B\"/></part-list>"
      "<part id=\"A\"><measure number=\"0\" implicit=\"yes\">" +
      divisions(1) + "</measure><measure number=\"1\">" + pitched("C", 5, 4) +
      "</measure></part>"
      "<part id=\"B\"><measure number=\"0\" implicit=\"yes\">"
      "<attributes><divisions>1</divisions><time><beats>4</beats><beat-type>4</beat-type>"
      "</time></attributes>" +
      pitched("G", 3, 1) + "</measure><measure number=\"1\">" + pitched("C", 3, 4) +
      "</measure></part></score-partwise>";
  const auto score = read_xml(xml);
  ASSERT_TRUE(score.ok()) << score.error().message;
  const auto a = notes_of_part(*score, 0);
  const auto b = notes_of_part(*score, 1);
  ASSERT_EQ(a.size(), 1u);
  ASSERT_EQ(b.size(), 2u);
  EXPECT_EQ(a[0].onset_ticks, kQ);
  EXPECT_EQ(b[1].onset_ticks, kQ);
  EXPECT_EQ(score->end_ticks, 5 * kQ);
}

TEST(MusicXmlReaderTest, SourceIndexCountsEveryNoteElement) {
  const auto score = read_xml(one_part_score(measure(
      divisions(1) + rest(1) + grace("D", 4) + pitched("C", 4, 1) +
      pitched("E", 4, 1, "", "<chord/>") + pitched("C", 4, 1, "", "<cue/>") + pitched("F", 4, 1))));
  ASSERT_TRUE(score.ok()) << score.error().message;
  std::vector<int> indices;
  for (const Note& note : score->notes) indices.push_back(note.source_index);
  EXPECT_EQ(indices, (std::vector<int>{1, 2, 3, 5}));
}

TEST(MusicXmlReaderTest, TimewiseScoresReadLikePartwise) {
  const std::string xml =
      "<score-timewise><part-list><score-part id=\"P1\"><part-name>Flute</part-name>"
      "</score-part><score-part id=\"P2\"/></part-list>"
      "<measure number=\"1\"><part id=\"P1\">" +
      divisions(1) + pitched("C", 5, 4) + "</part><part id=\"P2\">" + divisions(2) +
      pitched("C", 3, 8) +
      "</part></measure>"
      "<measure number=\"2\"><part id=\"P1\">" +
      pitched("D", 5, 4) + "</part></measure></score-timewise>";
  const auto score = read_xml(xml);
  ASSERT_TRUE(score.ok()) << score.error().message;
  ASSERT_EQ(score->parts.size(), 2u);
  EXPECT_EQ(score->parts[0].name, "Flute");
  const auto flute = notes_of_part(*score, 0);
  ASSERT_EQ(flute.size(), 2u);
  EXPECT_EQ(flute[1].onset_ticks, 4 * kQ);
  EXPECT_EQ(flute[1].source_index, 2);  // document order: C5, C3, D5
  EXPECT_EQ(notes_of_part(*score, 1).size(), 1u);
}

TEST(MusicXmlReaderTest, TimewiseScoresWithManyPartsStaySmallAndFast) {
  // 3000 parts that all appear only in the last of 30000 measures: memory and time follow the
  // elements present, not parts x measures (90 million).
  std::string xml = "<score-timewise><part-list>";
  for (int p = 0; p < 3000; ++p) xml += "<score-part id=\"P" + std::to_string(p) + "\"/>";
  xml += "</part-list>";
  for (int m = 0; m < 30000; ++m) xml += "<measure/>";
  xml += "<measure>";
  for (int p = 0; p < 3000; ++p) {
    xml += "<part id=\"P" + std::to_string(p) + "\">" + pitched("C", 4, 1) + "</part>";
  }
  xml += "</measure></score-timewise>";
  const auto start = std::chrono::steady_clock::now();
  const auto score = read_xml(xml);
  ASSERT_TRUE(score.ok()) << score.error().message;
  EXPECT_LT(std::chrono::steady_clock::now() - start, std::chrono::seconds(5));
  ASSERT_EQ(score->notes.size(), 3000u);
  EXPECT_EQ(score->notes[0].onset_ticks, 0);  // empty measures last no time
}

TEST(MusicXmlReaderTest, Utf16DocumentsAreRead) {
  const std::string utf8 = one_part_score(measure(divisions(1) + pitched("A", 4, 1)));
  std::string utf16 = "\xFF\xFE";
  for (const char c : utf8) {
    utf16 += c;
    utf16 += '\0';
  }
  const auto score = read_xml(utf16);
  ASSERT_TRUE(score.ok()) << score.error().message;
  ASSERT_EQ(score->notes.size(), 1u);
  EXPECT_EQ(score->notes[0].pitch, 69);
}

// --- hostile and broken inputs ------------------------------------------------------------

void expect_one_line_error(const std::string& input, const std::string& expected_part) {
  const auto start = std::chrono::steady_clock::now();
  const auto score = read_xml(input, "bad.musicxml");
  const auto elapsed = std::chrono::steady_clock::now() - start;
  ASSERT_FALSE(score.ok()) << "accepted: " << input.substr(0, 200);
  const std::string& message = score.error().message;
  EXPECT_EQ(message.rfind("bad.musicxml: ", 0), 0u) << message;
  EXPECT_EQ(message.find('\n'), std::string::npos) << message;
  EXPECT_EQ(message.find('\r'), std::string::npos) << message;
  EXPECT_NE(message.find(expected_part), std::string::npos) << message;
  EXPECT_LT(elapsed, std::chrono::seconds(5)) << message;
}

TEST(MusicXmlReaderTest, HostileInputsFailWithOneLineErrors) {
  const std::string good = one_part_score(measure(divisions(1) + pitched("C", 4, 4)));
  expect_one_line_error("", "empty file");
  expect_one_line_error(std::string("\x00\x01\x02\xff\xfe garbage", 13), "");
  expect_one_line_error("just some text", "no XML element");
  expect_one_line_error(good.substr(0, good.size() / 2), "line ");
  expect_one_line_error("<html>\n<body/></html>", "line 1: expected <score-partwise>");
  expect_one_line_error(
      one_part_score(measure(divisions(1) + "<note><pitch><step>C</step><octave>4</octave>"
                                            "</pitch><duration>1e18</duration></note>")),
      "part P1 measure 1: <duration> is absurdly long");
  expect_one_line_error(
      one_part_score(measure(divisions(1) + "<note><rest/><duration>-4</duration></note>")),
      "<duration> is negative");
  expect_one_line_error(
      one_part_score(measure(divisions(1) + "<backup><duration>-1</duration></backup>")),
      "<duration> of <backup> is negative");
  expect_one_line_error(
      one_part_score(measure(divisions(1) + "<note><rest/><duration>four</duration></note>")),
      "part P1 measure 1: <duration> is not a number");
  expect_one_line_error(one_part_score(measure(divisions(0) + pitched("C", 4, 4))),
                        "<divisions> must be a positive number");
  expect_one_line_error(one_part_score(measure(divisions(-4) + pitched("C", 4, 4))),
                        "<divisions> must be a positive number");
  expect_one_line_error(
      one_part_score(measure(divisions(1) + "<forward><duration>100000000000000000</duration>"
                                            "</forward>")),
      "absurdly long");
  // Many long forwards: the total passes 2^50 ticks without any loop per tick.
  std::string forwards;
  for (int i = 0; i < 3000; ++i)
    forwards += "<forward><duration>1000000000000</duration></forward>";
  expect_one_line_error(one_part_score(measure(divisions(1) + forwards)), "2^50");
  std::string measures;
  for (int i = 0; i < 3000; ++i) {
    measures +=
        measure(pitched("C", 4, 1000000000) + pitched("C", 4, 1000000000), std::to_string(i + 1));
  }
  expect_one_line_error(one_part_score(measure(divisions(1)) + measures), "2^50");
  expect_one_line_error(
      one_part_score(measure(divisions(1) + "<note><pitch><step>H</step><octave>4</octave>"
                                            "</pitch><duration>1</duration></note>")),
      "step must be one of A-G");
  expect_one_line_error(
      one_part_score(measure(divisions(1) + "<note><pitch><step>C</step><octave>x</octave>"
                                            "</pitch><duration>1</duration></note>")),
      "octave is not a whole number");
  expect_one_line_error(
      one_part_score(measure(divisions(1) + "<note><pitch><step>C</step><octave>4</octave>"
                                            "</pitch></note>")),
      "<note> has no <duration>");
  // A part id with a line break stays on one line in the message.
  expect_one_line_error("<score-partwise><part id=\"P&#10;1\"><measure number=\"7\">" +
                            divisions(0) + "</measure></part></score-partwise>",
                        "part P?1 measure 7");
  // Tempo changes cost the tempo map linear time each: their number is capped.
  std::string tempo_measures = measure(divisions(1));
  for (int i = 0; i < 12000; ++i) {
    tempo_measures += measure(
        std::string("<sound tempo=\"") + (i % 2 == 0 ? "60" : "61") + "\"/>" + pitched("C", 4, 1),
        std::to_string(i + 2));
  }
  expect_one_line_error(one_part_score(tempo_measures), "more than 10000 tempo changes");
  std::string deep = "<score-partwise><part id=\"P1\"><measure>";
  for (int i = 0; i < 100000; ++i) deep += "<a>";
  for (int i = 0; i < 100000; ++i) deep += "</a>";
  deep += "</measure></part></score-partwise>";
  expect_one_line_error(deep, "nested deeper than");
  expect_one_line_error(std::string("PK\x03\x04 this is not really a zip", 30),
                        "not a readable zip archive");
  const auto no_score = test::make_stored_zip({{"readme.txt", "hello"}});
  expect_one_line_error(std::string(no_score.begin(), no_score.end()),
                        "the archive holds no MusicXML score");
}

// --- .mxl ---------------------------------------------------------------------------------

std::string container_naming(const std::string& path) {
  return "<?xml version=\"1.0\"?><container><rootfiles>"
         "<rootfile full-path=\"cover.pdf\" media-type=\"application/pdf\"/>"
         "<rootfile full-path=\"" +
         path + "\"/></rootfiles></container>";
}

TEST(MusicXmlReaderTest, MxlRootFileComesFromTheContainer) {
  const std::string decoy = one_part_score(measure(divisions(1) + pitched("C", 4, 1)));
  const std::string real = one_part_score(measure(divisions(1) + pitched("E", 4, 1)));
  const auto zip =
      test::make_stored_zip({{"META-INF/container.xml", container_naming("s/real.xml")},
                             {"a-decoy.xml", decoy},
                             {"cover.pdf", "%PDF"},
                             {"s/real.xml", real}});
  const auto score = read_musicxml(zip, "song.mxl");
  ASSERT_TRUE(score.ok()) << score.error().message;
  ASSERT_EQ(score->notes.size(), 1u);
  EXPECT_EQ(score->notes[0].pitch, 64);
}

TEST(MusicXmlReaderTest, MxlWithoutContainerFallsBackToTheFirstScoreFile) {
  const std::string xml = one_part_score(measure(divisions(1) + pitched("G", 4, 1)));
  const auto zip = test::make_stored_zip(
      {{"META-INF/other.xml", "<x/>"}, {"notes.txt", "x"}, {"score.musicxml", xml}});
  const auto score = read_musicxml(zip, "song.mxl");
  ASSERT_TRUE(score.ok()) << score.error().message;
  ASSERT_EQ(score->notes.size(), 1u);
  EXPECT_EQ(score->notes[0].pitch, 67);
}

TEST(MusicXmlReaderTest, MxlInflationIsCapped) {
  const std::string xml = one_part_score(measure(divisions(1) + pitched("G", 4, 1)));
  const auto zip = test::make_stored_zip({{"score.xml", xml}});
  const auto capped = musicxml::read_mxl_score(zip, "song.mxl", 100);
  ASSERT_FALSE(capped.ok());
  EXPECT_EQ(capped.error().message,
            "song.mxl: score.xml inflates to more than 100 bytes (refusing a possible zip bomb)");
  const auto fits = musicxml::read_mxl_score(zip, "song.mxl", xml.size());
  ASSERT_TRUE(fits.ok()) << fits.error().message;
  EXPECT_EQ(*fits, xml);
}

}  // namespace
}  // namespace tutti::music
