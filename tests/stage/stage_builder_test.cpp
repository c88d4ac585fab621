// SPDX-License-Identifier: MIT
// Families plug into the stage through FamilyPlugin alone: a family of the test's own reads its
// own section of the scene file, adds a system, a performer and a model, and claims its notes;
// the stage's own frame systems (the clock, the notes' sounding) run for every family.
#include <tutti/stage/stage_builder.hpp>

#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <memory>
#include <nlohmann/json.hpp>
#include <string>
#include <type_traits>
#include <vector>

#include <tutti/brass/brass_players.hpp>
#include <tutti/components/note.hpp>
#include <tutti/components/performer.hpp>
#include <tutti/components/transform.hpp>
#include <tutti/piano/keyboard_players.hpp>
#include <tutti/stage/contact_detector.hpp>
#include <tutti/stage/family_draft.hpp>
#include <tutti/music/load_score.hpp>
#include <tutti/performance/draft_scene.hpp>
#include <tutti/performance/families.hpp>
#include <tutti/scene/load_scene.hpp>
#include "testdata.hpp"

namespace tutti::stage {
namespace {

// A bell's swing angle: what the test family's system writes every frame.
struct Swing {
  double angle_rad = 0.0;
};

// The test family's section of the scene file: "bells": {"ringer": NAME, "part": PART}.
struct Bells {
  std::string ringer;
  std::string part;
};

class BellSection final : public scene::SceneSection {
 public:
  std::string_view family() const override { return "bells"; }
  std::vector<std::string_view> keys() const override { return {"bells"}; }
  Status read(const nlohmann::json& document, const scene::SectionContext& context,
              scene::Scene& scene) const override {
    if (!document.contains("bells")) return Status::success();
    const nlohmann::json& object = document.at("bells");
    if (auto ok = context.fields().json().check_keys(object, "/bells", {"ringer", "part"}); !ok) {
      return ok;
    }
    Bells bells;
    auto ringer = context.fields().string(object, "/bells", "ringer");
    if (!ringer) return ringer.error();
    auto part = context.fields().string(object, "/bells", "part");
    if (!part) return part.error();
    bells.ringer = *ringer;
    bells.part = *part;
    scene.part_claims.push_back({bells.part, 0, "/bells/part", "/bells", /*exclusive=*/true});
    scene.sections.push_back({"bells", bells});
    return Status::success();
  }
};

// The test family's stop: the clapper strikes each time the swing passes a whole radian (value:
// that radian), found by a tracker of its own.
constexpr StopKind kBellStrike{"bell_strike", "bell strike", true};
// A stop's name reaches hosts as a C string, so only a string literal makes one: text that a
// family builds at run time (and frees) does not compile.
static_assert(!std::is_constructible_v<StopName, std::string>);
static_assert(!std::is_constructible_v<StopName, const char*>);
static_assert(kBellStrike.name == "bell_strike" && kBellStrike.name.c_str()[11] == '\0');
constexpr std::array<const StopKind*, 1> kBellStops{&kBellStrike};

class BellTracker final : public StopTracker {
 public:
  explicit BellTracker(ecs::Entity ringer) : ringer_(ringer) {}
  void sample(const ecs::World& world, const StopSample& sample,
              std::vector<Stop>& stops) override {
    const double angle = world.get<Swing>(ringer_).angle_rad;
    const double whole = std::floor(angle);
    if (!sample.first && whole > std::floor(previous_)) {
      stops.push_back({stop_crossing(sample.previous_t, previous_, sample.t, angle, whole),
                       &kBellStrike, ringer_, static_cast<std::int32_t>(whole), true});
    }
    previous_ = angle;
  }

 private:
  ecs::Entity ringer_;
  double previous_ = 0.0;
};

class BellFamily final : public FamilyPlugin {
 public:
  std::string_view name() const override { return "bells"; }
  const scene::SceneSection& scene_section() const override { return section_; }
  std::string_view draft_plays() const override { return "bells"; }
  int draft_seating_order() const override { return 5; }  // between the keyboards and brass
  // A bell ringer takes every part left, the first one's name for the ringer's.
  Result<std::vector<int>> draft_recognise(const music::Score&,
                                           std::span<const int> available) const override {
    return std::vector<int>(available.begin(), available.end());
  }
  Result<FamilyDraft> draft(const music::Score& score, std::span<const int> parts,
                            const DraftPlace& place) const override {
    FamilyDraft draft;
    draft.summary = "a bell ringer";
    draft.section.emplace_back(
        "bells", nlohmann::ordered_json{{"ringer", "Quasimodo"},
                                        {"part", draft_part_reference(score, parts.front())}});
    draft.cameras.push_back(draft_camera("bells", place.origin_x, 1.5, 3.0, place.origin_x, 1.0,
                                         0.0, 40.0));
    draft.groups.push_back({"bells", {parts.begin(), parts.end()}, {"bells"}});
    draft.left_m = place.origin_x - 0.5;
    draft.right_m = place.origin_x + 0.5;
    return draft;
  }
  void add_systems(ecs::Schedule& schedule) const override {
    schedule.add(ecs::Phase::evaluate, "bell_swing",
                 [](ecs::World& world, const ecs::FrameTime& frame) {
                   world.view<Swing>().each([&](Swing& swing) { swing.angle_rad = frame.t_s; });
                 });
  }
  std::span<const StopKind* const> stop_kinds() const override { return kBellStops; }
  std::unique_ptr<StopTracker> track_stops(ecs::World& world) const override {
    std::unique_ptr<StopTracker> tracker;
    world.view<const Swing>().each([&](ecs::Entity ringer, const Swing&) {
      tracker = std::make_unique<BellTracker>(ringer);
    });
    return tracker;
  }
  Status build(StageBuilder& builder) const override {
    const Bells* bells = builder.scene().section<Bells>("bells");
    const std::string ringer_name = bells != nullptr ? bells->ringer : "ringer";
    const ecs::Entity ringer =
        builder.add_performer(name(), 0, components::Performer{ringer_name, 5});
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
    builder.replanned(ringer_name);
    return Status::success();
  }

 private:
  BellSection section_;
};

// The piano demo staged with the bells as the only family.
std::unique_ptr<Stage> stage_with(const BellFamily& bells) {
  auto scene = scene::load_scene(tutti::test::source_dir() / "content" / "scenes" / "piano.json",
                                 performance::scene_load_options());
  EXPECT_TRUE(scene) << scene.error().message;
  if (!scene) return nullptr;
  const std::array<const FamilyPlugin*, 1> families{&bells};
  auto built = build_stage(*scene, families, {});
  EXPECT_TRUE(built) << built.error().message;
  return built ? std::move(*built) : nullptr;
}

TEST(StageBuilder, AFamilyOfItsOwnPlugsIn) {
  const BellFamily bells;
  auto built = stage_with(bells);
  ASSERT_NE(built, nullptr);
  Stage& stage = *built;
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

// A family names its own kinds of stop and finds them with a tracker of its own; the one
// detector asks it (the host API's events and sync-report read the detector).
TEST(StageBuilder, AFamilysStopsAreFoundByTheOneDetector) {
  const BellFamily bells;
  auto built = stage_with(bells);
  ASSERT_NE(built, nullptr);
  Stage& stage = *built;
  ASSERT_EQ(stage.families().size(), 1u);
  const std::vector<Stop> stops = detect_stops(stage, {0.5, 3.5, 0.01, false});
  ASSERT_EQ(stops.size(), 3u);
  for (std::size_t i = 0; i < stops.size(); ++i) {
    EXPECT_EQ(stops[i].kind, &kBellStrike);
    EXPECT_EQ(stops[i].performer, stage.find_performer("bells", 0));
    EXPECT_EQ(stops[i].value, static_cast<std::int32_t>(i + 1));
    EXPECT_NEAR(stops[i].t_s, static_cast<double>(i + 1), 1e-9);  // placed between samples
  }
}

// The piano demo with the bells ringing its part instead of the pianist.
nlohmann::json bell_scene(const nlohmann::json& bells) {
  std::ifstream in(tutti::test::source_dir() / "content" / "scenes" / "piano.json");
  nlohmann::json document = nlohmann::json::parse(in);
  document.erase("pianist");
  document["bells"] = bells;
  return document;
}

Result<scene::Scene> parse_with(const nlohmann::json& document,
                                const std::vector<const scene::SceneSection*>& extra) {
  scene::LoadOptions options = performance::scene_load_options();
  options.sections.insert(options.sections.end(), extra.begin(), extra.end());
  return scene::parse_scene(document, "s.json", tutti::test::source_dir() / "content" / "scenes",
                            options);
}

// A family's players are written under its own key, read by its own section: the loader and
// the Scene struct know nothing of bells.
TEST(StageBuilder, AFamilyReadsItsOwnSectionOfTheSceneFile) {
  const BellFamily bells;
  auto scene = parse_with(bell_scene({{"ringer", "Quasimodo"}, {"part", "Piano"}}),
                          {&bells.scene_section()});
  ASSERT_TRUE(scene) << scene.error().message;
  EXPECT_TRUE(piano::keyboard_players(*scene).empty());
  EXPECT_TRUE(brass::brass_players(*scene).empty());
  ASSERT_NE(scene->section<Bells>("bells"), nullptr);
  EXPECT_EQ(scene->section<Bells>("bells")->ringer, "Quasimodo");
  EXPECT_EQ(scene->section<int>("bells"), nullptr) << "read back only as the family's own type";
  EXPECT_EQ(scene->section<Bells>("chimes"), nullptr);
  ASSERT_EQ(scene->part_claims.size(), 1u);
  EXPECT_EQ(scene->part_claims[0].pointer, "/bells/part");

  const std::array<const FamilyPlugin*, 1> families{&bells};
  auto built = build_stage(*scene, families, {});
  ASSERT_TRUE(built) << built.error().message;
  const ecs::Entity ringer = (*built)->find_performer("bells", 0);
  ASSERT_FALSE(ringer.is_null());
  EXPECT_EQ((*built)->world().get<components::Performer>(ringer).name, "Quasimodo");
}

// The registered keys are the known ones: a key no family registers is an error, with a
// did-you-mean over the scene's keys and every family's; a family's errors name its keys.
TEST(StageBuilder, ASectionNoFamilyRegistersIsAnError) {
  const BellFamily bells;
  const nlohmann::json document = bell_scene({{"ringer", "Quasimodo"}, {"part", "Piano"}});
  auto unregistered = parse_with(document, {});
  ASSERT_FALSE(unregistered);
  EXPECT_EQ(unregistered.error().message, "s.json: /bells: unknown key");

  nlohmann::json typo = document;
  typo["bels"] = typo["bells"];
  typo.erase("bells");
  auto mistyped = parse_with(typo, {&bells.scene_section()});
  ASSERT_FALSE(mistyped);
  EXPECT_EQ(mistyped.error().message, "s.json: /bels: unknown key (did you mean \"bells\"?)");
  typo["pianistes"] = nlohmann::json::array();
  typo.erase("bels");
  auto piano_typo = parse_with(typo, {&bells.scene_section()});
  ASSERT_FALSE(piano_typo);
  EXPECT_EQ(piano_typo.error().message,
            "s.json: /pianistes: unknown key (did you mean \"pianists\"?)");

  nlohmann::json no_part = nlohmann::json::object();
  no_part["ringer"] = "Quasimodo";
  auto missing = parse_with(bell_scene(no_part), {&bells.scene_section()});
  ASSERT_FALSE(missing);
  EXPECT_EQ(missing.error().message, "s.json: /bells/part: missing");

  nlohmann::json nobody = document;
  nobody.erase("bells");
  auto empty = parse_with(nobody, {&bells.scene_section()});
  ASSERT_FALSE(empty);
  EXPECT_EQ(empty.error().message,
            "s.json: /: a scene needs at least one player (performers, pianists, pianist, "
            "bells)");
}

// The parts a family's players claim are checked against the music like everyone's: a part the
// music lacks, and an exclusive part a pianist plays too.
TEST(StageBuilder, AFamilysPartsAreCheckedAgainstTheMusic) {
  const BellFamily bells;
  auto scene = parse_with(bell_scene({{"ringer", "Quasimodo"}, {"part", "Carillon"}}),
                          {&bells.scene_section()});
  ASSERT_TRUE(scene) << scene.error().message;
  auto music = scene::load_scene_music(*scene);
  ASSERT_FALSE(music);
  EXPECT_EQ(music.error().message,
            "s.json: /bells/part: no part \"Carillon\" in ode_to_joy.musicxml (parts: Piano)");

  nlohmann::json shared = bell_scene({{"ringer", "Quasimodo"}, {"part", "Piano"}});
  nlohmann::json pianist = nlohmann::json::object();
  pianist["parts"] = nlohmann::json::array({"Piano"});
  shared["pianists"] = nlohmann::json::array({pianist});
  auto both = parse_with(shared, {&bells.scene_section()});
  ASSERT_TRUE(both) << both.error().message;
  auto clash = scene::load_scene_music(*both);
  ASSERT_FALSE(clash);
  EXPECT_EQ(clash.error().message,
            "s.json: /bells/part: part \"Piano\" is already played by /pianists/0/parts/0");
}

// `scene new` asks each family in turn for the parts it plays: a family listed after brass and
// the keyboards takes what they leave (a chorale's voices and timpani beside its trumpets), sits
// in its seating order (left of the brass), and its section, cameras and groups are in the
// drafted scene, which loads with its section registered.
TEST(StageBuilder, AFamilyDraftsItsPlayersForSceneNew) {
  TUTTI_REQUIRE_TESTDATA();
  const std::filesystem::path file = tutti::test::testdata("musicxml/music21/bwv29.8.mxl");
  auto score = music::load_score(file);
  ASSERT_TRUE(score) << score.error().message;
  auto alone = performance::draft_scene(*score, file);
  ASSERT_TRUE(alone) << alone.error().message;
  ASSERT_EQ(alone->notes.size(), 1u) << "the voices and timpani are not played";

  const BellFamily bells;
  std::vector<const FamilyPlugin*> families(performance::default_families().begin(),
                                            performance::default_families().end());
  families.push_back(&bells);
  auto drafted = performance::draft_scene(*score, file, families);
  ASSERT_TRUE(drafted) << drafted.error().message;
  EXPECT_TRUE(drafted->notes.empty()) << drafted->notes.front();
  const nlohmann::ordered_json& document = drafted->document;
  EXPECT_EQ(document["description"].get<std::string>(),
            "Made by tutti scene new from bwv29.8.mxl: 3 trumpets and a bell ringer.");
  ASSERT_TRUE(document.contains("bells"));
  EXPECT_EQ(document["bells"]["part"], "Soprano");
  // The bells sit left of the trumpets' arc, 1.4 m clear of it.
  double bells_x = 0.0;
  for (const auto& camera : document["cameras"]) {
    if (camera["name"] == "bells") bells_x = camera["position_m"][0].get<double>();
  }
  double leftmost_trumpet = 1e9;
  for (const auto& performer : document["performers"]) {
    leftmost_trumpet = std::min(leftmost_trumpet, performer["position_m"][0].get<double>());
  }
  EXPECT_NEAR(leftmost_trumpet - (bells_x + 0.5), 1.4, 1e-9);
  bool cut_to_bells = false;
  for (const auto& shot : document["shots"]) cut_to_bells = cut_to_bells || shot["camera"] == "bells";
  EXPECT_TRUE(cut_to_bells) << "the voices are the bells' group: the shots cut to them";

  auto scene = parse_with(nlohmann::json::parse(document.dump()), {&bells.scene_section()});
  ASSERT_TRUE(scene) << scene.error().message;
  EXPECT_EQ(brass::brass_players(*scene).size(), 3u);
  ASSERT_NE(scene->section<Bells>("bells"), nullptr);
  const Status parts = scene::check_scene_parts(*scene, {&*score, 1});
  EXPECT_TRUE(parts) << parts.error().message;
}

// Every note of the music is an entity: the quartet's are claimed by their players, and what is
// heard is read back from them.
TEST(StageBuilder, EveryNoteIsAnEntityWithItsPerformer) {
  auto scene = scene::load_scene(tutti::test::source_dir() / "content" / "scenes" / "quartet.json",
                                 performance::scene_load_options());
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
  for (std::size_t seat = 0; seat < brass::brass_players(*scene).size(); ++seat) {
    const auto& where =
        stage.world().get<components::Transform>(stage.find_performer("brass", seat));
    EXPECT_DOUBLE_EQ(where.x_mm, brass::brass_players(*scene)[seat].position_m.x * 1000.0);
    EXPECT_DOUBLE_EQ(where.z_mm, brass::brass_players(*scene)[seat].position_m.z * 1000.0);
    const double turned =
        2.0 * std::atan2(where.rotation.y, where.rotation.w) * 180.0 / 3.14159265358979323846;
    EXPECT_NEAR(turned, brass::brass_players(*scene)[seat].facing_deg, 1e-9);
  }
  EXPECT_TRUE(stage.note_entity(1, 0).is_null());
}

}  // namespace
}  // namespace tutti::stage
