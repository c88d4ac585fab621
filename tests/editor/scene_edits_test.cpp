// SPDX-License-Identifier: MIT
// The editor's edits build the scene the loader reads: breath marks, cues, expressions, cuts,
// pins, variation and seeds, each undone exactly.
#include <tutti/editor/scene_edits.hpp>

#include <gtest/gtest.h>

#include <tutti/brass/brass_players.hpp>
#include <tutti/editor/document.hpp>
#include <tutti/piano/keyboard_players.hpp>
#include "editor_test_support.hpp"

namespace tutti::editor {
namespace {

using test::performer_at;
using test::ScratchDir;

// A scene file written with one "pianist" object.
const PlayerRef kPianist{"/pianist", ""};

class SceneEdits : public ::testing::Test {
 protected:
  void SetUp() override {
    auto doc = Document::open(dir_.copy_scene("quartet.json"));
    ASSERT_TRUE(doc) << doc.error().message;
    doc_ = std::make_unique<Document>(std::move(*doc));
  }
  void apply(Result<Edit> edit) {
    ASSERT_TRUE(edit) << edit.error().message;
    const Status s = doc_->apply(std::move(*edit));
    ASSERT_TRUE(s) << s.error().message;
  }
  const scene::Scene& scene() const { return doc_->scene(); }

  ScratchDir dir_;
  std::unique_ptr<Document> doc_;
};

TEST_F(SceneEdits, BreathMarks) {
  apply(add_breath(doc_->json(), performer_at(1), 7.25));
  apply(add_breath(doc_->json(), performer_at(1), 3.5));
  EXPECT_EQ(brass::brass_players(scene())[1].breaths.add_s, (std::vector<double>{3.5, 7.25}));
  // Deleting a marked breath drops the mark; deleting a planned one adds a "remove".
  apply(delete_breath(doc_->json(), performer_at(1), 7.25, /*marked_only=*/true));
  apply(delete_breath(doc_->json(), performer_at(1), 10.0));
  EXPECT_EQ(brass::brass_players(scene())[1].breaths.add_s, (std::vector<double>{3.5}));
  EXPECT_EQ(brass::brass_players(scene())[1].breaths.remove_s, (std::vector<double>{10.0}));
  // Adding where a breath was removed undoes the removal.
  apply(add_breath(doc_->json(), performer_at(1), 10.0));
  EXPECT_TRUE(brass::brass_players(scene())[1].breaths.remove_s.empty());
  apply(move_breath(doc_->json(), performer_at(1), 3.5, /*from_marked_only=*/true, 4.0));
  EXPECT_EQ(brass::brass_players(scene())[1].breaths.add_s, (std::vector<double>{4.0}));
  // Everything undone: no "breaths" key left.
  while (doc_->can_undo()) ASSERT_TRUE(doc_->undo());
  EXPECT_FALSE(doc_->json()["performers"][1].contains("breaths"));
  EXPECT_FALSE(doc_->dirty());
}

TEST_F(SceneEdits, CuesStartFromTheAutomaticOne) {
  EXPECT_FALSE(scene().cues_s.has_value());
  const std::vector<double> automatic{2.0};
  apply(add_cue(doc_->json(), automatic, 16.0));
  ASSERT_TRUE(scene().cues_s.has_value());
  EXPECT_EQ(*scene().cues_s, (std::vector<double>{2.0, 16.0}));
  apply(move_cue(doc_->json(), *scene().cues_s, 1, 15.5));
  EXPECT_EQ(*scene().cues_s, (std::vector<double>{2.0, 15.5}));
  apply(delete_cue(doc_->json(), *scene().cues_s, 0));
  EXPECT_EQ(*scene().cues_s, (std::vector<double>{15.5}));
  EXPECT_FALSE(delete_cue(doc_->json(), *scene().cues_s, 4));
}

TEST_F(SceneEdits, Expressions) {
  scene::Expression strain{scene::ExpressionKind::strain, 4.0, 6.0, 0.8};
  scene::Expression relaxed{scene::ExpressionKind::relaxed, 1.0, 2.0, 1.0};
  apply(add_expression(doc_->json(), performer_at(0), strain));
  apply(add_expression(doc_->json(), performer_at(0), relaxed));
  ASSERT_EQ(brass::brass_players(scene())[0].expressions.size(), 2u);
  EXPECT_EQ(brass::brass_players(scene())[0].expressions[0], relaxed);  // in start order
  EXPECT_EQ(brass::brass_players(scene())[0].expressions[1], strain);
  apply(move_expression(doc_->json(), performer_at(0), strain, 5.0));
  const scene::Expression moved{scene::ExpressionKind::strain, 5.0, 7.0, 0.8};
  EXPECT_EQ(brass::brass_players(scene())[0].expressions[1], moved) << "the same length, later";
  ASSERT_TRUE(doc_->undo());
  apply(delete_expression(doc_->json(), performer_at(0), strain));
  EXPECT_EQ(brass::brass_players(scene())[0].expressions, std::vector<scene::Expression>{relaxed});
  EXPECT_FALSE(delete_expression(doc_->json(), performer_at(0), strain));
  // An expression the loader refuses (end before start) is refused by the document.
  auto backwards =
      add_expression(doc_->json(), performer_at(0), {scene::ExpressionKind::strain, 5.0, 4.0, 1.0});
  ASSERT_TRUE(backwards);
  EXPECT_FALSE(doc_->apply(*backwards));
}

TEST_F(SceneEdits, CameraCuts) {
  const std::size_t shots = scene().shots.size();
  apply(add_shot(doc_->json(), "wide", 32.0));
  ASSERT_EQ(scene().shots.size(), shots + 1);
  EXPECT_EQ(scene().cameras[scene().shots[scene().shot_at(32.5)].camera].name, "wide");
  apply(move_shot(doc_->json(), 1, 1.25));
  EXPECT_DOUBLE_EQ(scene().shots[1].start_s, 1.25);
  apply(delete_shot(doc_->json(), 1));
  EXPECT_EQ(scene().shots.size(), shots);
  EXPECT_FALSE(delete_shot(doc_->json(), 0)) << "the first shot stays";
  auto unknown = add_shot(doc_->json(), "nobody", 3.0);
  ASSERT_TRUE(unknown);
  EXPECT_FALSE(doc_->apply(*unknown)) << "no camera of that name: the loader says so";
}

TEST_F(SceneEdits, VariationAndSeed) {
  apply(set_variation(doc_->json(), performer_at(2), "head_motion", 0.75));
  EXPECT_DOUBLE_EQ(*brass::brass_players(scene())[2].variation.head_motion, 0.75);
  apply(set_variation(doc_->json(), performer_at(2), "head_motion", std::nullopt));
  EXPECT_FALSE(brass::brass_players(scene())[2].variation.head_motion.has_value());
  EXPECT_FALSE(doc_->json()["performers"][2].contains("variation"));
  EXPECT_FALSE(set_variation(doc_->json(), performer_at(2), "swagger", 0.5));
  const std::uint64_t seed = brass::brass_players(scene())[2].seed;
  apply(set_seed(doc_->json(), performer_at(2), reroll_seed(seed)));
  EXPECT_NE(brass::brass_players(scene())[2].seed, seed);
  EXPECT_EQ(reroll_seed(seed), reroll_seed(seed)) << "deterministic";
  EXPECT_FALSE(set_seed(doc_->json(), PlayerRef{"/pianist", ""}, 1))
      << "the quartet has no pianist";
}

TEST(SceneEditsPiano, PinAndUnpin) {
  ScratchDir dir;
  auto doc = Document::open(dir.copy_scene("piano.json"));
  ASSERT_TRUE(doc) << doc.error().message;
  ASSERT_TRUE(doc->apply(*pin_finger(doc->json(), kPianist, 1.5, 64, 3)));
  ASSERT_TRUE(
      doc->apply(*pin_finger(doc->json(), kPianist, 1.5, 64, 2)));  // the same note: replaced
  ASSERT_EQ(piano::keyboard_players(doc->scene()).front().pins.size(), 1u);
  EXPECT_EQ(piano::keyboard_players(doc->scene()).front().pins[0], (piano::FingerPin{1.5, 64, 2}));
  ASSERT_TRUE(doc->apply(*unpin_finger(doc->json(), kPianist, 1.5, 64)));
  EXPECT_TRUE(piano::keyboard_players(doc->scene()).front().pins.empty());
  EXPECT_FALSE(doc->json()["pianist"].contains("pins"));
  EXPECT_FALSE(unpin_finger(doc->json(), kPianist, 1.5, 64));
}

// With two pianists, each pin, seed and variation goes to the pianist it is about, at
// "/pianists/<index>", and the other pianist's entry is left as it was.
TEST(SceneEditsPiano, TwoPianistsEachTheirOwn) {
  ScratchDir dir;
  auto doc = Document::open(dir.copy_scene("piano_duo.json"));
  ASSERT_TRUE(doc) << doc.error().message;
  const Json first = doc->json()["pianists"][0];
  auto pin = pin_finger(doc->json(), PlayerRef{"/pianists/1", ""}, 0.0, 64,
                        2);  // Piano II's first note, E4
  ASSERT_TRUE(pin) << pin.error().message;
  ASSERT_EQ(pin->changes.size(), 1u);
  EXPECT_EQ(pin->changes[0].pointer, "/pianists/1/pins");
  ASSERT_TRUE(doc->apply(std::move(*pin)));
  EXPECT_TRUE(piano::keyboard_players(doc->scene())[0].pins.empty());
  ASSERT_EQ(piano::keyboard_players(doc->scene())[1].pins.size(), 1u);
  EXPECT_EQ(piano::keyboard_players(doc->scene())[1].pins[0], (piano::FingerPin{0.0, 64, 2}));
  auto seed = set_seed(doc->json(), PlayerRef{"/pianists/1", "pianist 2"}, 99);
  ASSERT_TRUE(seed) << seed.error().message;
  EXPECT_EQ(seed->label, "new seed for pianist 2");
  ASSERT_TRUE(doc->apply(std::move(*seed)));
  EXPECT_EQ(piano::keyboard_players(doc->scene())[1].seed, 99u);
  EXPECT_EQ(doc->json()["pianists"][0], first);
  EXPECT_FALSE(pin_finger(doc->json(), PlayerRef{"/pianists/2", ""}, 0.0, 64, 2))
      << "there is no third pianist";
}

}  // namespace
}  // namespace tutti::editor
