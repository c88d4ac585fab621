// SPDX-License-Identifier: MIT
// Families plug into the stage through FamilyPlugin alone: a family of the test's own adds a
// system, a performer and a model, and claims its notes; the stage's own frame systems (the
// clock, the notes' sounding) run for every family.
#include <tutti/stage/stage_builder.hpp>

#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <filesystem>

#include <tutti/components/note.hpp>
#include <tutti/components/performer.hpp>
#include <tutti/components/transform.hpp>
#include <tutti/performance/families.hpp>
#include <tutti/scene/load_scene.hpp>

namespace tutti::stage {
namespace {

const std::filesystem::path kSource(TUTTI_SOURCE_DIR);

// A bell's swing angle: what the test family's system writes every frame.
struct Swing {
  double angle_rad = 0.0;
};

class BellFamily final : public FamilyPlugin {
 public:
  std::string_view name() const override { return "bells"; }
  void add_systems(ecs::Schedule& schedule) const override {
    schedule.add(ecs::Phase::evaluate, "bell_swing",
                 [](ecs::World& world, const ecs::FrameTime& frame) {
                   world.view<Swing>().each([&](Swing& swing) { swing.angle_rad = frame.t_s; });
                 });
  }
  Status build(StageBuilder& builder) const override {
    const ecs::Entity ringer =
        builder.add_performer(name(), 0, components::Performer{"ringer", 5});
    builder.world().add<Swing>(ringer);
    auto bell = builder.generated_model("chair.glb");
    if (!bell) return bell.error();
    PlacedModel& placed = builder.placed(builder.place(*bell, glm::mat4(1.0f)));
    placed.performer = ringer;
    placed.after_performer = true;
    // The ringer plays every note of the first score.
    for (std::size_t i = 0; i < builder.scores().front().notes.size(); ++i) {
      builder.world().get<components::Note>(builder.note_entity(0, i)).performer = ringer;
    }
    builder.replanned("ringer");
    return Status::success();
  }
};

TEST(StageBuilder, AFamilyOfItsOwnPlugsIn) {
  auto scene = scene::load_scene(kSource / "content" / "scenes" / "piano.json");
  ASSERT_TRUE(scene) << scene.error().message;
  const BellFamily bells;
  const std::array<const FamilyPlugin*, 1> families{&bells};
  auto built = build_stage(*scene, families, {});
  ASSERT_TRUE(built) << built.error().message;
  Stage& stage = **built;
  // Only the families given: the scene's pianist has no family here.
  ASSERT_EQ(stage.performers().size(), 1u);
  const ecs::Entity ringer = stage.find_performer("bells", 0);
  ASSERT_FALSE(ringer.is_null());
  EXPECT_TRUE(stage.find_performer("piano", 0).is_null());
  EXPECT_EQ(stage.world().get<components::Performer>(ringer).name, "ringer");
  EXPECT_EQ(stage.schedule().describe(),
            "sync: audio_sync\nevaluate: note_sounding, bell_swing\n");
  EXPECT_EQ(stage.replanned(), std::vector<std::string>{"ringer"});
  ASSERT_EQ(stage.instances().size(), 2u);  // the floor, then the family's model
  EXPECT_EQ(stage.placed(1).performer, ringer);

  stage.run({2.5, 0.0});
  EXPECT_EQ(stage.world().get<Swing>(ringer).angle_rad, 2.5);
  // The notes are the ringer's, and sound as the frame's time says.
  const music::Score& score = stage.scores().front();
  std::size_t sounding = 0;
  for (std::size_t i = 0; i < score.notes.size(); ++i) {
    const auto& note = stage.world().get<components::Note>(stage.note_entity(0, i));
    EXPECT_EQ(note.performer, ringer);
    EXPECT_EQ(note.sounding, note.onset_s <= 2.5 && 2.5 < note.offset_s) << i;
    sounding += note.sounding ? 1 : 0;
  }
  EXPECT_GT(sounding, 0u);
}

// Every note of the music is an entity: the quartet's are claimed by their players, and what is
// heard is read back from them.
TEST(StageBuilder, EveryNoteIsAnEntityWithItsPerformer) {
  auto scene = scene::load_scene(kSource / "content" / "scenes" / "quartet.json");
  ASSERT_TRUE(scene) << scene.error().message;
  auto built = performance::build_stage(*scene);
  ASSERT_TRUE(built) << built.error().message;
  Stage& stage = **built;
  const music::Score& score = stage.scores().front();
  ASSERT_EQ(stage.world().size<components::Note>(), score.notes.size());
  std::size_t claimed = 0;
  for (std::size_t i = 0; i < score.notes.size(); ++i) {
    const auto& note = stage.world().get<components::Note>(stage.note_entity(0, i));
    EXPECT_EQ(note.pitch, score.notes[i].pitch);
    EXPECT_EQ(note.written_onset_s, score.notes[i].onset_s);
    EXPECT_EQ(note.written_offset_s, score.notes[i].offset_s);
    EXPECT_LE(note.offset_s, note.written_offset_s);
    if (note.performer.is_null()) continue;
    ++claimed;
    EXPECT_EQ(stage.world().get<Seat>(note.performer).family, "brass");
  }
  EXPECT_EQ(claimed, score.notes.size()) << "each of the four parts has its player";
  EXPECT_TRUE(stage.note_entity(0, score.notes.size()).is_null());
  // Each player stands where the scene says (Transform: mm, a turn about +Y).
  for (std::size_t seat = 0; seat < scene->performers.size(); ++seat) {
    const auto& where =
        stage.world().get<components::Transform>(stage.find_performer("brass", seat));
    EXPECT_DOUBLE_EQ(where.x_mm, scene->performers[seat].position_m.x * 1000.0);
    EXPECT_DOUBLE_EQ(where.z_mm, scene->performers[seat].position_m.z * 1000.0);
    const double turned =
        2.0 * std::atan2(where.rotation.y, where.rotation.w) * 180.0 / 3.14159265358979323846;
    EXPECT_NEAR(turned, scene->performers[seat].facing_deg, 1e-9);
  }
  EXPECT_TRUE(stage.note_entity(1, 0).is_null());
}

}  // namespace
}  // namespace tutti::stage
