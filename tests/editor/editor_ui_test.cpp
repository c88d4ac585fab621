// SPDX-License-Identifier: MIT
// The editor's panels driven headless: a bare ImGui context (no window, no renderer), the mouse
// moved and clicked through ImGuiIO for a few frames, and the model checked afterwards.
#include <tutti/brass/brass_players.hpp>
#include <tutti/editor/editor_ui.hpp>

#include <gtest/gtest.h>
#include <imgui.h>

#include <algorithm>
#include <cmath>

#include "editor_test_support.hpp"

namespace tutti::editor {
namespace {

using test::performer_at;
using test::ScratchDir;

class EditorUi : public ::testing::Test {
 protected:
  void SetUp() override {
    IMGUI_CHECKVERSION();
    ImGui::CreateContext();
    ImGuiIO& io = ImGui::GetIO();
    io.DisplaySize = ImVec2(1280, 720);
    io.IniFilename = nullptr;
    io.DeltaTime = 1.0f / 60.0f;
    unsigned char* pixels = nullptr;
    int w = 0, h = 0;
    io.Fonts->GetTexDataAsRGBA32(&pixels, &w, &h);  // builds the font atlas
    for (int key = 0; key < ImGuiKey_COUNT; ++key) io.KeyMap[key] = key;
  }
  void TearDown() override { ImGui::DestroyContext(); }

  UiRequests frame(Session& session) {
    ImGui::NewFrame();
    UiRequests requests = draw_editor(session, ui_);
    ImGui::Render();
    return requests;
  }
  // Presses the left button at (x, y) for one frame and releases it the next.
  void click(Session& session, float x, float y) {
    ImGuiIO& io = ImGui::GetIO();
    io.MousePos = ImVec2(x, y);
    frame(session);  // hover first, as a real mouse does
    io.MouseDown[0] = true;
    frame(session);
    io.MouseDown[0] = false;
    frame(session);
  }
  const WidgetBox& widget(const std::string& id) {
    const WidgetBox* box = find_widget(ui_, id);
    EXPECT_NE(box, nullptr) << id;
    static const WidgetBox none;
    return box != nullptr ? *box : none;
  }

  ScratchDir dir_;
  UiState ui_;
};

TEST_F(EditorUi, DraggingASliderSetsTheVariationAsOneUndoStep) {
  auto session = Session::open(dir_.copy_scene("quartet.json"));
  ASSERT_TRUE(session) << session.error().message;
  Session& s = **session;
  ui_.selected_lane = 2;  // Trombone 1: no variation in the file
  frame(s);
  const WidgetBox box = widget("inspector/sway_amount");
  ASSERT_GT(box.x1, box.x0);
  ImGuiIO& io = ImGui::GetIO();
  const float y = (box.y0 + box.y1) / 2;
  io.MousePos = ImVec2(box.x0 + 0.25f * (box.x1 - box.x0), y);
  frame(s);
  io.MouseDown[0] = true;
  frame(s);
  for (float f : {0.4f, 0.6f, 0.75f}) {  // drag right, frame by frame
    io.MousePos = ImVec2(box.x0 + f * (box.x1 - box.x0), y);
    frame(s);
  }
  io.MouseDown[0] = false;
  frame(s);
  const auto& value = brass::brass_players(s.document().scene())[2].variation.sway_amount;
  ASSERT_TRUE(value.has_value());
  EXPECT_NEAR(*value, 0.75, 0.06);  // the grab's width offsets the mapping a little
  EXPECT_EQ(s.document().history().size(), 1u) << "one drag, one undo step";
  EXPECT_EQ(s.document().undo_label(), "set sway_amount of Trombone 1");
}

TEST_F(EditorUi, ClickingReRollChangesTheSeedAndUndoRestoresIt) {
  auto session = Session::open(dir_.copy_scene("quartet.json"));
  ASSERT_TRUE(session) << session.error().message;
  Session& s = **session;
  ui_.selected_lane = 1;
  frame(s);
  const std::uint64_t seed = brass::brass_players(s.document().scene())[1].seed;
  const WidgetBox reroll = widget("inspector/reroll");
  click(s, (reroll.x0 + reroll.x1) / 2, (reroll.y0 + reroll.y1) / 2);
  EXPECT_EQ(brass::brass_players(s.document().scene())[1].seed, reroll_seed(seed));
  const WidgetBox undo = widget("transport/undo");
  click(s, (undo.x0 + undo.x1) / 2, (undo.y0 + undo.y1) / 2);
  EXPECT_EQ(brass::brass_players(s.document().scene())[1].seed, seed);
}

TEST_F(EditorUi, ClickingTheRulerSeeks) {
  auto session = Session::open(dir_.copy_scene("quartet.json"));
  ASSERT_TRUE(session) << session.error().message;
  Session& s = **session;
  ui_.view_start_s = 0.0;
  ui_.view_length_s = 20.0;
  frame(s);
  const WidgetBox ruler = widget("timeline/ruler");
  ImGuiIO& io = ImGui::GetIO();
  io.MousePos = ImVec2(ruler.x0 + 0.5f * (ruler.x1 - ruler.x0), (ruler.y0 + ruler.y1) / 2);
  frame(s);
  io.MouseDown[0] = true;
  const UiRequests pressed = frame(s);
  io.MouseDown[0] = false;
  frame(s);
  ASSERT_TRUE(pressed.seek_s.has_value());
  EXPECT_NEAR(*pressed.seek_s, 10.0, 0.05);
}

// Right-click a lane where the music is legato, choose "Breathe here": a breath mark at the next
// note; click the new breath, press Delete: gone again.
TEST_F(EditorUi, ALanesMenuAddsABreathAndDeleteRemovesIt) {
  auto session = Session::open(dir_.copy_scene("quartet.json"));
  ASSERT_TRUE(session) << session.error().message;
  Session& s = **session;
  ui_.view_start_s = 0.0;
  ui_.view_length_s = 20.0;
  frame(s);
  const WidgetBox lane = widget("timeline/lane/Trombone 1");
  const auto x_of = [&](double t) {
    return lane.x0 + static_cast<float>(t / 20.0) * (lane.x1 - lane.x0);
  };
  const float y = (lane.y0 + lane.y1) / 2;
  ImGuiIO& io = ImGui::GetIO();
  io.MousePos = ImVec2(x_of(6.3), y);  // inside a note, 0.37 s before the next (legato) one
  frame(s);
  io.MouseDown[1] = true;
  frame(s);
  io.MouseDown[1] = false;
  frame(s);
  frame(s);
  const WidgetBox item = widget("lane_popup/breathe");
  click(s, (item.x0 + item.x1) / 2, (item.y0 + item.y1) / 2);
  const auto& marks = brass::brass_players(s.document().scene())[2].breaths.add_s;
  ASSERT_EQ(marks.size(), 1u) << ui_.status;
  const double boundary = s.breath_boundary(performer_at(2), 6.3);
  // The mark names the next note, where it was asked for (written to the millisecond).
  EXPECT_EQ(marks[0], std::round(boundary * 1000.0) / 1000.0);
  const TimelineBreath* added = nullptr;
  for (const TimelineBreath& b : s.timeline().lanes[2].breaths) {
    if (std::abs(b.boundary_s - boundary) < 1e-6) added = &b;
  }
  ASSERT_NE(added, nullptr);
  EXPECT_TRUE(added->marked);

  click(s, x_of(added->boundary_s), y);  // select it
  EXPECT_EQ(ui_.selection, UiState::Selection::breath);
  io.KeysDown[ImGuiKey_Delete] = true;
  frame(s);
  io.KeysDown[ImGuiKey_Delete] = false;
  frame(s);
  EXPECT_TRUE(brass::brass_players(s.document().scene())[2].breaths.add_s.empty()) << ui_.status;
  EXPECT_TRUE(brass::brass_players(s.document().scene())[2].breaths.remove_s.empty())
      << "a marked breath leaves no remove mark behind";
  EXPECT_EQ(s.document().history().size(), 2u);
}

// Drag a camera cut along the cameras row and drop it on a beat: the shot starts there.
TEST_F(EditorUi, DraggingACutMovesIt) {
  auto session = Session::open(dir_.copy_scene("quartet.json"));
  ASSERT_TRUE(session) << session.error().message;
  Session& s = **session;
  ui_.view_start_s = 0.0;
  ui_.view_length_s = 20.0;
  frame(s);
  const WidgetBox row = widget("timeline/cameras");
  const auto x_of = [&](double t) {
    return row.x0 + static_cast<float>(t / 20.0) * (row.x1 - row.x0);
  };
  const float y = (row.y0 + row.y1) / 2;
  const double from = s.document().scene().shots[1].start_s;  // 3.5 s
  const auto found = std::find_if(s.timeline().beats_s.begin(), s.timeline().beats_s.end(),
                                  [](double t) { return t > 5.0; });
  ASSERT_NE(found, s.timeline().beats_s.end());
  const double target = *found;  // a copy: the drop re-plans and replaces the timeline
  ImGuiIO& io = ImGui::GetIO();
  io.MousePos = ImVec2(x_of(from), y);
  frame(s);
  io.MouseDown[0] = true;
  frame(s);
  for (double t = from; t < target; t += 0.25) {
    io.MousePos = ImVec2(x_of(t), y);
    frame(s);
  }
  io.MousePos = ImVec2(x_of(target) + 1.0f, y);  // a pixel off: it snaps onto the beat
  frame(s);
  io.MouseDown[0] = false;
  frame(s);
  EXPECT_DOUBLE_EQ(s.document().scene().shots[1].start_s, target) << ui_.status;
  EXPECT_EQ(s.document().history().size(), 1u);
}

TEST_F(EditorUi, QuittingWithUnsavedChangesAsksFirst) {
  auto session = Session::open(dir_.copy_scene("quartet.json"));
  ASSERT_TRUE(session) << session.error().message;
  Session& s = **session;
  ui_.quit_requested = true;
  EXPECT_TRUE(frame(s).quit) << "nothing unsaved: quit at once";
  ASSERT_TRUE(s.apply(add_breath(s.document().json(), performer_at(0), 5.0)));
  ui_.quit_requested = true;
  EXPECT_FALSE(frame(s).quit) << "unsaved: a prompt, not a quit";
  frame(s);
  const WidgetBox save = widget("prompt/save");
  ImGuiIO& io = ImGui::GetIO();
  io.MousePos = ImVec2((save.x0 + save.x1) / 2, (save.y0 + save.y1) / 2);
  frame(s);
  io.MouseDown[0] = true;
  frame(s);
  io.MouseDown[0] = false;
  EXPECT_TRUE(frame(s).quit);
  EXPECT_FALSE(s.document().dirty()) << "saved before quitting";
}

}  // namespace
}  // namespace tutti::editor
