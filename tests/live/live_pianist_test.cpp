// SPDX-License-Identifier: MIT
// The pianist playing live input: scripted events through the same source interface as MIDI,
// a 60 fps frame loop, and the latency from each event to its key contact (press depth 1 in the
// evaluated pose), which must stay within one frame; the pose at t must depend only on the
// events that had arrived by t.
#include <tutti/live/live_pianist.hpp>

#include <gtest/gtest.h>

#include <algorithm>
#include <cstdio>
#include <map>
#include <random>

#include <tutti/finger_motion/evaluate_hand_pose.hpp>
#include <tutti/live/scripted_source.hpp>
#include <tutti/piano_model/content_dir.hpp>

namespace tutti::live {
namespace {

constexpr double kFrameS = 1.0 / 60.0;

std::unique_ptr<LivePianist> make_pianist(const LivePianistOptions& options = {}) {
  auto model = fingering_planner::load_fingering_model();
  EXPECT_TRUE(model.ok());
  auto params = finger_motion::load_finger_motion_params(
      finger_motion::finger_motion_params_path(piano_model::default_content_dir()));
  EXPECT_TRUE(params.ok());
  auto pianist = LivePianist::create(std::move(*model), *params, options);
  EXPECT_TRUE(pianist.ok()) << pianist.error().message;
  return std::move(*pianist);
}

// A deterministic improvisation: melody notes and three-note chords (arriving over 12 ms, as
// played by hand) in both hands, at times that fall anywhere between frames, some exactly on
// a frame.
std::vector<LiveNoteEvent> improvisation(int notes, unsigned seed) {
  std::mt19937 random(seed);
  std::uniform_real_distribution<double> gap(0.06, 0.4), length(0.05, 0.6), unit(0.0, 1.0);
  std::vector<LiveNoteEvent> events;
  double t = 0.25;
  int right = 72, left = 48;
  for (int i = 0; i < notes; ++i) {
    t += gap(random);
    if (i % 7 == 3) t = std::round(t * 60.0) / 60.0;  // on a frame
    const bool in_left = unit(random) < 0.4;
    int& last = in_left ? left : right;
    last = std::clamp(last + static_cast<int>(unit(random) * 9.0) - 4, in_left ? 36 : 62,
                      in_left ? 58 : 88);
    const bool chord = i % 5 == 0;
    const double hold = length(random);
    for (int k = 0; k < (chord ? 3 : 1); ++k) {
      const int key = last + 4 * k - (in_left ? 8 : 0);
      events.push_back({t + 0.006 * k, key, 90, true});
      events.push_back({t + 0.006 * k + hold, key, 0, false});
    }
  }
  return events;
}

struct Latency {
  std::vector<double> s;  // per note-on, event to contact
  int missing = 0;
};

// Runs the frame loop over `events` and measures each note's contact: the first frame whose
// evaluated pose has the note's finger at press depth 1 on its key. Also records every frame's
// pose of every finger (for the causality check).
struct FrameLoop {
  Latency latency;
  std::vector<std::pair<double, std::array<finger_motion::HandPose, 2>>> frames;
  std::unique_ptr<LivePianist> pianist;
};

FrameLoop run_frames(std::vector<LiveNoteEvent> events, double seconds,
                     const LivePianistOptions& options) {
  FrameLoop r;
  r.pianist = make_pianist(options);
  ScriptedSource source(std::move(events));
  std::vector<LiveNoteEvent> polled;
  std::map<std::int64_t, double> waiting;  // note id -> event time, until its contact is seen
  std::int64_t seen_id = 0;
  for (int k = 0; k * kFrameS <= seconds; ++k) {
    const double now = k * kFrameS;
    polled.clear();
    source.poll(now, polled);
    r.pianist->update(polled, now);
    const auto& played = r.pianist->played();
    for (const LivePlayed& p : played) {
      if (p.id > seen_id) waiting[p.id] = p.event_s;
    }
    if (!played.empty()) seen_id = std::max(seen_id, played.back().id);
    const finger_motion::PianistMotion& motion = *r.pianist->motion();
    std::array<finger_motion::HandPose, 2> poses{};
    for (int h = 0; h < 2; ++h) {
      const auto side = h == 0 ? components::HandSide::right : components::HandSide::left;
      finger_motion::evaluate_hand_pose(motion.fingers, motion.path(side), side, now,
                                        poses[static_cast<std::size_t>(h)]);
    }
    r.frames.push_back({now, poses});
    for (auto it = waiting.begin(); it != waiting.end();) {
      const auto p = std::find_if(played.begin(), played.end(),
                                  [&](const LivePlayed& x) { return x.id == it->first; });
      const auto& finger = poses[p->hand == music::Hand::left ? 1 : 0]
                               .fingers[static_cast<std::size_t>(p->finger - 1)];
      if (finger.key == p->key && finger.press_depth >= 1.0 - 1e-9) {
        r.latency.s.push_back(now - it->second);
        it = waiting.erase(it);
      } else if (now - it->second > 0.5) {
        ++r.latency.missing;
        std::printf("missing: id %lld key %d hand %d finger %d event %.4f contact %.4f\n",
                    static_cast<long long>(p->id), p->key, static_cast<int>(p->hand), p->finger,
                    p->event_s, p->contact_s);
        it = waiting.erase(it);
      } else {
        ++it;
      }
    }
  }
  return r;
}

TEST(LivePianist, KeyContactWithinOneFrameOfTheEvent) {
  const auto events = improvisation(200, 8);
  const FrameLoop r = run_frames(events, events.back().time_s + 1.0, {});
  const int note_ons = static_cast<int>(
      std::count_if(events.begin(), events.end(), [](const LiveNoteEvent& e) { return e.on; }));
  EXPECT_EQ(r.pianist->ignored_notes(), 0);
  EXPECT_EQ(r.latency.missing, 0);
  ASSERT_EQ(static_cast<int>(r.latency.s.size()), note_ons);
  std::vector<double> sorted = r.latency.s;
  std::sort(sorted.begin(), sorted.end());
  double sum = 0.0;
  for (double s : sorted) sum += s;
  std::printf(
      "latency event -> key contact, %zu notes at 60 fps: mean %.2f ms, median %.2f ms, "
      "p95 %.2f ms, max %.2f ms (one frame = %.2f ms)\n",
      sorted.size(), 1e3 * sum / static_cast<double>(sorted.size()),
      1e3 * sorted[sorted.size() / 2], 1e3 * sorted[sorted.size() * 95 / 100], 1e3 * sorted.back(),
      1e3 * kFrameS);
  EXPECT_LE(sorted.back(), kFrameS + 1e-9);
  EXPECT_GE(sorted.front(), 0.0);
  // Both hands played, and chords were spread over fingers.
  int left = 0;
  for (const LivePlayed& p : r.pianist->played()) left += p.hand == music::Hand::left ? 1 : 0;
  EXPECT_GT(left, 20);
}

TEST(LivePianist, PoseAtTDependsOnlyOnWhatHadArrived) {
  // Every frame's pose, computed when only the events up to that frame had arrived, is the
  // pose the final motion gives for that time (nothing is pruned: room for every contact and move).
  LivePianistOptions options;
  options.contacts_per_finger = 1000;
  options.moves_per_hand = 1000;
  const auto events = improvisation(60, 3);
  const FrameLoop r = run_frames(events, events.back().time_s + 1.0, options);
  const finger_motion::PianistMotion& final_motion = *r.pianist->motion();
  int compared = 0;
  for (const auto& [t, poses] : r.frames) {
    for (int h = 0; h < 2; ++h) {
      const auto side = h == 0 ? components::HandSide::right : components::HandSide::left;
      finger_motion::HandPose again;
      finger_motion::evaluate_hand_pose(final_motion.fingers, final_motion.path(side), side, t,
                                        again);
      const finger_motion::HandPose& then = poses[static_cast<std::size_t>(h)];
      ASSERT_NEAR(again.x_mm, then.x_mm, 1e-9) << "t " << t;
      for (std::size_t f = 0; f < 5; ++f) {
        ASSERT_EQ(again.fingers[f].key, then.fingers[f].key) << "t " << t << " finger " << f;
        ASSERT_NEAR(again.fingers[f].press_depth, then.fingers[f].press_depth, 1e-9);
        ASSERT_NEAR(again.fingers[f].tip_x_mm, then.fingers[f].tip_x_mm, 1e-6);
        ++compared;
      }
    }
  }
  EXPECT_GT(compared, 1000);
}

TEST(LivePianist, ChordArrivingOverMillisecondsGetsDistinctFingers) {
  auto pianist = make_pianist();
  // C E G in the right hand, 5 ms apart, seen in one frame.
  const std::vector<LiveNoteEvent> chord = {
      {0.100, 60, 90, true}, {0.105, 64, 90, true}, {0.110, 67, 90, true}};
  EXPECT_TRUE(pianist->update(chord, 0.1167));
  ASSERT_EQ(pianist->played().size(), 3u);
  std::vector<int> fingers;
  for (const LivePlayed& p : pianist->played()) {
    EXPECT_EQ(p.hand, music::Hand::right);
    fingers.push_back(p.finger);
    EXPECT_EQ(p.contact_s, 0.1167);  // the key is down in the frame that saw it
  }
  EXPECT_LT(fingers[0], fingers[1]);
  EXPECT_LT(fingers[1], fingers[2]);
  // Released: the keys come up.
  const std::vector<LiveNoteEvent> off = {
      {0.3, 60, 0, false}, {0.3, 64, 0, false}, {0.3, 67, 0, false}};
  EXPECT_TRUE(pianist->update(off, 0.3));
  finger_motion::HandPose pose;
  const auto& motion = *pianist->motion();
  finger_motion::evaluate_hand_pose(motion.fingers, motion.right_path, components::HandSide::right,
                                    0.5, pose);
  for (const auto& f : pose.fingers) EXPECT_EQ(f.press_depth, 0.0);
  // Nothing new: no new motion.
  EXPECT_FALSE(pianist->update({}, 0.6));
}

TEST(LivePianist, OutOfRangeKeysAreClampedOrIgnored) {
  auto pianist = make_pianist();
  const std::vector<LiveNoteEvent> events = {{0.0, 5, 90, true}, {0.0, 200, 90, true}};
  pianist->update(events, 0.0);
  EXPECT_EQ(pianist->ignored_notes(), 1);  // 200 is no MIDI key; 5 is played as A0
  ASSERT_EQ(pianist->played().size(), 1u);
  EXPECT_EQ(pianist->played()[0].key, 21);
}

}  // namespace
}  // namespace tutti::live
