// SPDX-License-Identifier: MIT
// A scene open in the editor: edits keep it valid, undo/redo restore it exactly, saving is
// atomic with a backup, and unsaved work survives in the autosave side file.
#include <tutti/editor/document.hpp>

#include <gtest/gtest.h>

#include <tutti/brass/brass_players.hpp>
#include <tutti/editor/atomic_file.hpp>
#include <tutti/editor/scene_edits.hpp>
#include "editor_test_support.hpp"
#include <tutti/scene/load_scene.hpp>
#include <tutti/performance/families.hpp>

namespace tutti::editor {
namespace {

using test::performer_at;
using test::read_text;
using test::ScratchDir;

TEST(Document, OpensTheShippedScenes) {
  for (const char* name : {"quartet.json", "piano.json"}) {
    auto doc = Document::open(test::source_dir() / "content" / "scenes" / name);
    ASSERT_TRUE(doc) << doc.error().message;
    EXPECT_FALSE(doc->dirty());
    EXPECT_FALSE(doc->can_undo());
  }
  auto missing = Document::open("/no/such/scene.json");
  ASSERT_FALSE(missing);
  EXPECT_EQ(missing.error().message, "/no/such/scene.json: no such file");
}

TEST(Document, EditUndoRedo) {
  ScratchDir dir;
  auto doc = Document::open(dir.copy_scene("quartet.json"));
  ASSERT_TRUE(doc) << doc.error().message;
  const Json original = doc->json();
  const double before = *brass::brass_players(doc->scene())[1].variation.sway_amount;
  auto edit = set_variation(doc->json(), performer_at(1), "sway_amount", 0.9);
  ASSERT_TRUE(edit) << edit.error().message;
  ASSERT_TRUE(doc->apply(*edit));
  EXPECT_DOUBLE_EQ(*brass::brass_players(doc->scene())[1].variation.sway_amount, 0.9);
  EXPECT_TRUE(doc->dirty());
  EXPECT_EQ(doc->undo_label(), "set sway_amount of Trumpet 2");
  ASSERT_TRUE(doc->undo());
  EXPECT_DOUBLE_EQ(*brass::brass_players(doc->scene())[1].variation.sway_amount, before);
  EXPECT_TRUE(same_json(doc->json(), original));
  EXPECT_FALSE(doc->dirty());
  ASSERT_TRUE(doc->redo());
  EXPECT_DOUBLE_EQ(*brass::brass_players(doc->scene())[1].variation.sway_amount, 0.9);
  // A new edit clears the redo list.
  ASSERT_TRUE(doc->undo());
  ASSERT_TRUE(doc->apply(*set_seed(doc->json(), performer_at(0), 99)));
  EXPECT_FALSE(doc->can_redo());
  EXPECT_EQ(brass::brass_players(doc->scene())[0].seed, 99u);
}

TEST(Document, AnEditThatBreaksTheSceneIsRefused) {
  ScratchDir dir;
  auto doc = Document::open(dir.copy_scene("quartet.json"));
  ASSERT_TRUE(doc);
  const std::uint64_t revision = doc->revision();
  auto edit = set_variation(doc->json(), performer_at(0), "sway_amount", 1.5);
  ASSERT_TRUE(edit);
  const Status s = doc->apply(*edit);
  ASSERT_FALSE(s);
  EXPECT_EQ(s.error().message,
            "quartet.json: /performers/0/variation/sway_amount: must be in [0, 1]");
  EXPECT_EQ(doc->revision(), revision);
  EXPECT_FALSE(doc->dirty());
  EXPECT_FALSE(doc->can_undo());
}

TEST(Document, SaveWritesWhatWasEditedAndKeepsABackup) {
  ScratchDir dir;
  const auto file = dir.copy_scene("quartet.json");
  const std::string original = read_text(file);
  auto doc = Document::open(file);
  ASSERT_TRUE(doc);
  ASSERT_TRUE(doc->apply(*add_breath(doc->json(), performer_at(2), 6.0)));
  ASSERT_TRUE(doc->save());
  EXPECT_FALSE(doc->dirty());
  EXPECT_EQ(read_text(backup_path(file)), original);
  auto reloaded = scene::load_scene(file, performance::scene_load_options());
  ASSERT_TRUE(reloaded) << reloaded.error().message;
  EXPECT_EQ(brass::brass_players(*reloaded)[2].breaths.add_s, std::vector<double>{6.0});
  EXPECT_EQ(brass::brass_players(*reloaded), brass::brass_players(doc->scene()));
  // Everything else as it was (the same scene, field for field).
  auto first = scene::load_scene(backup_path(file), performance::scene_load_options());
  ASSERT_TRUE(first) << first.error().message;
  brass::edit_brass_players(*reloaded)[2].breaths = {};
  EXPECT_EQ(brass::brass_players(*reloaded), brass::brass_players(*first));
  EXPECT_EQ(reloaded->shots.size(), first->shots.size());
  // The saved text keeps the file's key order and short arrays on one line.
  const std::string saved = read_text(file);
  EXPECT_LT(saved.find("\"description\""), saved.find("\"music\""));
  EXPECT_NE(saved.find("\"breaths\": {\"add\": [6.0]}"), std::string::npos) << saved;
}

TEST(Document, UnsavedEditsSurviveInTheAutosave) {
  ScratchDir dir;
  const auto file = dir.copy_scene("quartet.json");
  const std::string original = read_text(file);
  {
    auto doc = Document::open(file);
    ASSERT_TRUE(doc);
    ASSERT_TRUE(doc->autosave());
    EXPECT_FALSE(std::filesystem::exists(Document::autosave_path(file))) << "nothing unsaved";
    ASSERT_TRUE(doc->apply(*set_variation(doc->json(), performer_at(2), "breath_depth", 0.25)));
    ASSERT_TRUE(doc->autosave());
    EXPECT_TRUE(std::filesystem::exists(Document::autosave_path(file)));
    // The editor "crashes" here: no save.
  }
  EXPECT_EQ(read_text(file), original) << "the autosave never writes over the scene";
  auto doc = Document::open(file);
  ASSERT_TRUE(doc);
  ASSERT_TRUE(doc->autosave_available());
  EXPECT_FALSE(brass::brass_players(doc->scene())[2].variation.breath_depth.has_value());
  ASSERT_TRUE(doc->recover_autosave());
  EXPECT_DOUBLE_EQ(*brass::brass_players(doc->scene())[2].variation.breath_depth, 0.25);
  EXPECT_TRUE(doc->dirty());
  EXPECT_EQ(doc->undo_label(), "recover unsaved changes");
  ASSERT_TRUE(doc->save());
  EXPECT_FALSE(std::filesystem::exists(Document::autosave_path(file))) << "saved: no side file";
  auto again = Document::open(file);
  ASSERT_TRUE(again);
  EXPECT_FALSE(again->autosave_available());
}

}  // namespace
}  // namespace tutti::editor
