// SPDX-License-Identifier: MIT
#pragma once
// The editor's panels (Dear ImGui 1.86), drawn over the 3D view: the transport, the timeline
// (bars and beats, each performer's notes, breaths, expressions, the cues and the camera cuts),
// the performer inspector (variation sliders, seed re-roll) and a fingered player's fingers and
// hand area. Every change goes through Session::apply, so it is undoable and re-planned at once.
//
// draw_editor() only reads input through ImGui and returns what the host must do with the
// transport (seek, play, quit): it needs no window, so tests drive it headless with a bare ImGui
// context (tests/editor/editor_ui_test.cpp).

#include <cstddef>
#include <optional>
#include <string>
#include <vector>

#include <tutti/editor/session.hpp>

namespace tutti::editor {

// A widget's screen rectangle, recorded each frame for tests and scripts ("inspector/sway_amount").
struct WidgetBox {
  std::string id;
  float x0 = 0, y0 = 0, x1 = 0, y1 = 0;
};

// An edit asked for while drawing: applied after the frame's panels are drawn, because applying
// re-plans and replaces the scene and timeline the panels are reading.
struct PendingAction {
  enum class Kind { edit, undo, redo, recover };
  Kind kind = Kind::edit;
  std::optional<Edit> edit;
  bool coalesce = false;
};

struct UiState {
  double time_s = 0.0;   // the playhead (the host's transport sets it each frame)
  bool playing = false;  // ditto
  double tempo = 1.0;
  std::size_t selected_lane = 0;  // into Timeline::lanes
  // What is selected on the timeline (Delete removes it).
  enum class Selection { none, breath, cue, expression, shot };
  Selection selection = Selection::none;
  std::size_t selected_index = 0;  // breath / expression in the lane, cue, shot
  double view_start_s = 0.0;       // the timeline's visible span
  double view_length_s = 20.0;
  std::string status;           // the last message (an edit refused, saved, ...)
  bool quit_requested = false;  // the host asks (window close); the UI prompts when unsaved
  bool offer_recovery = false;  // ask once whether to recover the autosave
  std::vector<WidgetBox> widgets;
  // Dragging a timeline mark: what, from where.
  int drag_kind = -1;
  std::size_t drag_index = 0;
  double drag_from_s = 0.0;
  bool drag_marked = false;  // a breath there only because of its mark
  std::size_t pin_note = 0;  // the note (of a fingered lane) whose finger popup is open
  double context_s = 0.0;    // where the open context menu was asked for (snapped)
  std::vector<PendingAction> pending;
};

struct UiRequests {
  std::optional<double> seek_s;
  bool toggle_play = false;
  std::optional<double> tempo;
  bool quit = false;  // confirmed (saved, discarded or nothing unsaved)
};

UiRequests draw_editor(Session& session, UiState& ui);

// The recorded box of a widget, nullptr if it was not drawn this frame.
const WidgetBox* find_widget(const UiState& ui, const std::string& id);

}  // namespace tutti::editor
