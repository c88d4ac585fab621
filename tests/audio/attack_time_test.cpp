// SPDX-License-Identifier: MIT
// Attack compensation (audio/attack_time.hpp) with Debian's General MIDI font: attacks measured
// per instrument (a trombone speaks later than a trumpet, a trumpet later than a piano), a line
// with a slur and a rest heard on its score times once compensated, and the limits kept.
#include <tutti/audio/attack_time.hpp>

#include <gtest/gtest.h>

#include <cmath>

#include <tutti/audio/offline_synth.hpp>
#include <tutti/audio/onset_detection.hpp>
#include <tutti/audio/sound_font.hpp>

namespace tutti::audio {
namespace {

class AttackTimeTest : public ::testing::Test {
 protected:
  void SetUp() override {
    auto font = find_sound_font();
    ASSERT_TRUE(font) << font.error().message;
    font_ = *font;
  }
  std::filesystem::path font_;
};

TEST_F(AttackTimeTest, TromboneSpeaksLaterThanTrumpetAndTrumpetLaterThanPiano) {
  const SampledNote notes[] = {{0, 60, 80}, {56, 60, 80}, {57, 53, 80}};
  auto attacks = measure_attack_times(font_, notes, 48000);
  ASSERT_TRUE(attacks) << attacks.error().message;
  const double piano = (*attacks)[0], trumpet = (*attacks)[1], trombone = (*attacks)[2];
  std::printf("attacks: piano %.1f ms, trumpet %.1f ms, trombone %.1f ms\n", piano * 1000,
              trumpet * 1000, trombone * 1000);
  EXPECT_GT(piano, 0.0);
  EXPECT_LT(piano, 0.015);
  EXPECT_GT(trumpet, piano);
  EXPECT_GT(trombone, trumpet + 0.01);
  EXPECT_LE(trombone, 0.1);
}

// A trombone line: an entrance, a slur, a rest, a repeated entrance; and a trumpet chord note
// beside it. Compensated, each is heard within 5 ms of its score time.
TEST_F(AttackTimeTest, ACompensatedLineIsHeardOnItsScoreTimes) {
  music::Score score;
  music::Part trombone;
  trombone.program = 57;
  score.parts.push_back(trombone);
  const double onsets[] = {0.5, 1.2, 2.2, 2.9};
  const double offsets[] = {1.2, 1.8, 2.6, 3.4};
  const int keys[] = {53, 58, 55, 50};
  for (std::size_t i = 0; i < 4; ++i) {
    music::Note note;
    note.pitch = keys[i];
    note.onset_s = onsets[i];
    note.offset_s = offsets[i];
    note.velocity = 90;
    score.notes.push_back(note);
  }
  const music::Score* scores[] = {&score};
  auto timeline = build_synth_timeline(scores, {});
  ASSERT_TRUE(timeline) << timeline.error().message;
  SynthTimeline plain = *timeline;
  auto stats = compensate_attacks(*timeline, font_);
  ASSERT_TRUE(stats) << stats.error().message;
  EXPECT_EQ(stats->notes, 4);
  EXPECT_EQ(stats->moved, 4);
  EXPECT_GT(stats->mean_advance_s, 0.02);

  // The slur's old note is released with the new one; ordering holds.
  std::int64_t slur_on = -1, slur_off = -1;
  for (const SynthEvent& e : timeline->events) {
    if (e.kind == SynthEventKind::note_on && e.note == 1) slur_on = e.frame;
    if (e.kind == SynthEventKind::note_off && e.note == 0) slur_off = e.frame;
  }
  EXPECT_EQ(slur_on, slur_off);
  EXPECT_LT(slur_on, 48000 * 12 / 10);
  for (std::size_t i = 1; i < timeline->events.size(); ++i) {
    EXPECT_LE(timeline->events[i - 1].frame, timeline->events[i].frame);
  }

  auto heard = [&](const SynthTimeline& t) {
    auto audio = render_timeline(t, {.sound_font = font_});
    EXPECT_TRUE(audio);
    std::vector<double> times;
    for (const Onset& o : detect_onsets(*audio)) times.push_back(o.time_s);
    return times;
  };
  const std::vector<double> before = heard(plain);
  const std::vector<double> after = heard(*timeline);
  auto nearest = [](const std::vector<double>& times, double t) {
    double best = 1e9;
    for (double x : times) best = std::abs(x - t) < std::abs(best - t) ? x : best;
    return best;
  };
  // (The low D3's sample swells again some 45 ms in: one onset more than notes.)
  EXPECT_GE(after.size(), 4u);
  EXPECT_LE(after.size(), 5u);
  for (std::size_t i = 0; i < 4; ++i) {
    EXPECT_NEAR(nearest(after, onsets[i]), onsets[i], 0.005) << "note " << i;
    EXPECT_GT(nearest(before, onsets[i]) - onsets[i], 0.02)
        << "note " << i << ": uncompensated, the trombone speaks late";
  }

  // Deterministic.
  SynthTimeline again = plain;
  ASSERT_TRUE(compensate_attacks(again, font_));
  ASSERT_EQ(again.events.size(), timeline->events.size());
  for (std::size_t i = 0; i < again.events.size(); ++i) {
    EXPECT_EQ(again.events[i].frame, timeline->events[i].frame);
  }
}

TEST_F(AttackTimeTest, NotesNeverMoveIntoTheNoteBeforeNorPercussion) {
  music::Score score;
  music::Part trumpet;
  trumpet.program = 56;
  score.parts.push_back(trumpet);
  music::Part drums;
  drums.percussion = true;
  score.parts.push_back(drums);
  // 5 ms of rest before the second note: it may move no further than that.
  for (auto [onset, offset, part] : {std::tuple{0.5, 0.9, 0}, {0.905, 1.3, 0}, {0.5, 0.6, 1}}) {
    music::Note note;
    note.pitch = part == 0 ? 60 : 38;
    note.onset_s = onset;
    note.offset_s = offset;
    note.velocity = 90;
    note.part = part;
    score.notes.push_back(note);
  }
  const music::Score* scores[] = {&score};
  auto timeline = build_synth_timeline(scores, {});
  ASSERT_TRUE(timeline) << timeline.error().message;
  const SynthTimeline plain = *timeline;
  ASSERT_TRUE(compensate_attacks(*timeline, font_));
  auto frame_of_event = [](const SynthTimeline& t, SynthEventKind kind, int note) {
    for (const SynthEvent& e : t.events) {
      if (e.kind == kind && e.note == note) return e.frame;
    }
    return std::int64_t{-1};
  };
  EXPECT_LT(frame_of_event(*timeline, SynthEventKind::note_on, 0),
            frame_of_event(plain, SynthEventKind::note_on, 0));
  EXPECT_GE(frame_of_event(*timeline, SynthEventKind::note_on, 1),
            frame_of_event(*timeline, SynthEventKind::note_off, 0));
  EXPECT_EQ(frame_of_event(*timeline, SynthEventKind::note_on, 2),
            frame_of_event(plain, SynthEventKind::note_on, 2))
      << "percussion stays";
}

TEST_F(AttackTimeTest, AMissingSoundFontIsAnError) {
  const SampledNote notes[] = {{56, 60, 80}};
  auto attacks = measure_attack_times("/nonexistent/font.sf2", notes, 48000);
  ASSERT_FALSE(attacks);
  EXPECT_NE(attacks.error().message.find("/nonexistent/font.sf2"), std::string::npos);
}

}  // namespace
}  // namespace tutti::audio
