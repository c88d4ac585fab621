// SPDX-License-Identifier: MIT
// An organist on third-party music: a Bach chorale's four voices (music21 corpus, bwv29.8) on the
// organ, the bass on the pedals. Measured from the posed skeleton over the whole
// piece: every toe holding a pedal down is on it, no foot holds two pedals, and the pedal notes
// are the bass's.
#include <tutti/stage/stage.hpp>

#include <gtest/gtest.h>

#include <algorithm>
#include <fstream>
#include <vector>

#include <tutti/components/note.hpp>
#include <tutti/model/model_asset.hpp>
#include <tutti/performance/families.hpp>
#include <tutti/piano/piano_components.hpp>
#include <tutti/piano_model/pedal_geometry.hpp>
#include <tutti/scene/load_scene.hpp>
#include "scratch_dir.hpp"
#include "testdata.hpp"

namespace tutti::stage {
namespace {

using piano::FeetPlan;
using piano::PedalPress;
using piano::PianoRig;

TEST(Organist, PlaysABachChoralesBassOnThePedals) {
  const std::filesystem::path chorale = tutti::test::testdata("musicxml/music21/bwv29.8.mxl");
  if (!std::filesystem::exists(chorale)) GTEST_SKIP() << "no " << chorale;
  tutti::test::ScratchDir dir;
  const std::filesystem::path scene_path = dir.path() / "organ_chorale.json";
  std::ofstream(scene_path) << R"({"music": ")" << chorale.string()
                            << R"(", "pianists": [{"instrument": "organ",
                               "parts": ["Soprano", "Alto", "Tenor", "Bass"]}],
                               "cameras": [{"name": "wide", "position_m": [1.5, 1.5, 2.5],
                                            "target_m": [0, 0.8, 0], "fov_deg": 45}]})";
  auto scene = scene::load_scene(scene_path, performance::scene_load_options());
  ASSERT_TRUE(scene) << scene.error().message;
  auto built = performance::build_stage(*scene, {});
  ASSERT_TRUE(built) << built.error().message;
  Stage& stage = **built;
  const ecs::World& world = stage.world();
  const ecs::Entity organist = stage.find_performer("piano", 0);
  ASSERT_FALSE(organist.is_null());
  const PianoRig& rig = world.get<PianoRig>(organist);
  ASSERT_TRUE(rig.feet);
  const FeetPlan& feet = *rig.feet;
  const music::Score& score = stage.scores().front();
  const auto bass = static_cast<int>(std::find_if(score.parts.begin(), score.parts.end(),
                                                  [](const music::Part& p) { return p.name == "Bass"; }) -
                                     score.parts.begin());
  // The feet play the bass (the lowest of the four parts, a single line), the hands the rest.
  std::size_t bass_notes = 0;
  for (const music::Note& n : score.notes) bass_notes += n.part == bass ? 1 : 0;
  ASSERT_GT(bass_notes, 30u);
  EXPECT_EQ(feet.presses.size(), bass_notes);
  for (const PedalPress& press : feet.presses) {
    const music::Note& n = score.notes[press.note];
    EXPECT_EQ(n.part, bass);
    EXPECT_EQ(press.key, n.pitch) << "within the pedals' compass: not moved";
    EXPECT_EQ(world.get<components::Note>(stage.note_entity(0, press.note)).performer, organist);
  }
  // No foot holds two pedals at once, nor presses one before it has let the last one up.
  for (const auto& mine : feet.by_foot) {
    for (std::size_t j = 1; j < mine.size(); ++j) {
      EXPECT_LT(feet.presses[mine[j - 1]].up_s, feet.presses[mine[j]].down_s);
    }
  }
  // Over the whole piece, the toe on each pedal held down.
  std::vector<glm::mat4> organ_world, body_world;
  double worst_mm = 0.0;
  std::size_t checked = 0;
  const double end_s = feet.presses.back().up_s;
  for (int k = 0; k / 30.0 <= end_s; ++k) {
    const double t = k / 30.0;
    evaluate_stage(stage, t);
    const auto& organ = world.get<PlacedModel>(rig.piano);
    const auto& body = world.get<PlacedModel>(rig.body);
    organ_world.resize(organ.asset->nodes.size());
    body_world.resize(body.asset->nodes.size());
    model::compute_world_matrices(*organ.asset, organ.pose, organ.root, organ_world);
    model::compute_world_matrices(*body.asset, body.pose, body.root, body_world);
    for (const PedalPress& press : feet.presses) {
      if (t < press.down_s || t > press.up_s) continue;
      const int toe =
          press.foot == piano::kRightFoot ? rig.body_nodes.toe_right : rig.body_nodes.toe_left;
      const int pedal = rig.pedal_nodes[static_cast<std::size_t>(press.key)];
      ASSERT_GE(toe, 0);
      ASSERT_GE(pedal, 0);
      const float along = static_cast<float>(piano_model::pedal_is_sharp(press.key)
                                                 ? piano_model::PedalGeometry::kSharpToe_m
                                                 : piano_model::PedalGeometry::kNaturalToe_m);
      const glm::vec3 expected = glm::vec3(organ_world[static_cast<std::size_t>(pedal)] *
                                           glm::vec4(0.0f, 0.0f, along, 1.0f));
      const glm::vec3 at = glm::vec3(body_world[static_cast<std::size_t>(toe)][3]);
      worst_mm = std::max(worst_mm, 1000.0 * static_cast<double>(glm::distance(at, expected)));
      ++checked;
    }
  }
  EXPECT_GT(checked, 100u);
  EXPECT_LT(worst_mm, 1.0) << "a toe off the pedal it holds down";
}

// The bundled organ scene (content/scenes/organ.json): its part is written on three staves, and
// the third is the pedals'. Each note of it is a pedal press, every other note the hands'.
TEST(Organist, TheThirdStaffIsThePedals) {
  auto scene = scene::load_scene(std::filesystem::path(TUTTI_SOURCE_DIR) / "content" / "scenes" /
                                 "organ.json", performance::scene_load_options());
  ASSERT_TRUE(scene) << scene.error().message;
  auto built = performance::build_stage(*scene, {});
  ASSERT_TRUE(built) << built.error().message;
  const Stage& stage = **built;
  const PianoRig& rig = stage.world().get<PianoRig>(stage.find_performer("piano", 0));
  ASSERT_TRUE(rig.feet);
  const music::Score& score = stage.scores().front();
  std::vector<bool> pedal(score.notes.size(), false);
  for (const PedalPress& press : rig.feet->presses) pedal[press.note] = true;
  std::size_t third_staff = 0;
  for (std::size_t i = 0; i < score.notes.size(); ++i) {
    EXPECT_EQ(pedal[i], score.notes[i].staff == 3) << "note " << i;
    third_staff += score.notes[i].staff == 3 ? 1 : 0;
  }
  EXPECT_GT(third_staff, 25u);
  EXPECT_FALSE(rig.feet->by_foot[piano::kLeftFoot].empty());
  EXPECT_FALSE(rig.feet->by_foot[piano::kRightFoot].empty());
}

}  // namespace
}  // namespace tutti::stage
