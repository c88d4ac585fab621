// SPDX-License-Identifier: MIT
#include <tutti/editor/editor_ui.hpp>

#include <imgui.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>

#include <tutti/ensemble_variation/variation_params.hpp>
#include <tutti/runtime/input_bindings.hpp>

namespace tutti::editor {
namespace {

constexpr float kTransportHeight = 44.0f;
constexpr float kTimelineHeight = 300.0f;
constexpr float kInspectorWidth = 330.0f;
constexpr float kLabelWidth = 110.0f;
constexpr float kRulerHeight = 22.0f;
constexpr float kRowHeight = 20.0f;
constexpr float kLaneHeight = 34.0f;
constexpr float kGrabPixels = 6.0f;

constexpr ImGuiWindowFlags kPanelFlags = ImGuiWindowFlags_NoMove | ImGuiWindowFlags_NoResize |
                                         ImGuiWindowFlags_NoCollapse |
                                         ImGuiWindowFlags_NoSavedSettings;

// The seed-drawn value of each variation field (scene::kVariationFields order).
constexpr std::array<double ensemble_variation::VariationParams::*, 7> kParamOf{
    &ensemble_variation::VariationParams::sway_amount,  &ensemble_variation::VariationParams::sway_period,
    &ensemble_variation::VariationParams::sway_phase,   &ensemble_variation::VariationParams::weight_shift_rate,
    &ensemble_variation::VariationParams::breath_depth, &ensemble_variation::VariationParams::cue_strength,
    &ensemble_variation::VariationParams::head_motion};

// The panels are designed in sRGB colours; the swap chain encodes linear light (the layer
// linearises ImGui's own style the same way), so each colour is decoded once here.
ImU32 srgb(int r, int g, int b, int a = 255) {
  auto linear = [](int c) {
    const float v = static_cast<float>(c) / 255.0f;
    const float l = v <= 0.04045f ? v / 12.92f : std::pow((v + 0.055f) / 1.055f, 2.4f);
    return static_cast<int>(std::lround(l * 255.0f));
  };
  return IM_COL32(linear(r), linear(g), linear(b), a);
}

void record(UiState& ui, const std::string& id) {
  const ImVec2 a = ImGui::GetItemRectMin();
  const ImVec2 b = ImGui::GetItemRectMax();
  ui.widgets.push_back({id, a.x, a.y, b.x, b.y});
}

// Queues an edit for the end of the frame; a builder's refusal goes to the status line.
void apply(Session& /*session*/, UiState& ui, Result<Edit> edit, bool coalesce = false) {
  if (!edit) {
    ui.status = edit.error().message;
    return;
  }
  PendingAction action;
  action.edit = std::move(*edit);
  action.coalesce = coalesce;
  ui.pending.push_back(std::move(action));
}

void request(UiState& ui, PendingAction::Kind kind) {
  PendingAction action;
  action.kind = kind;
  ui.pending.push_back(std::move(action));
}

// After drawing: each queued action re-plans; a refused one says why in the status line.
void run_pending(Session& session, UiState& ui) {
  for (PendingAction& action : ui.pending) {
    Status s;
    std::string done;
    switch (action.kind) {
      case PendingAction::Kind::edit:
        done = action.edit->label;
        s = session.apply(std::move(*action.edit), action.coalesce);
        break;
      case PendingAction::Kind::undo:
        done = "undid " + session.document().undo_label();
        s = session.undo();
        break;
      case PendingAction::Kind::redo:
        done = "redid " + session.document().redo_label();
        s = session.redo();
        break;
      case PendingAction::Kind::recover:
        done = "recovered the autosave";
        s = session.recover_autosave();
        break;
    }
    ui.status = s ? done : s.error().message;
  }
  ui.pending.clear();
}

std::string clock_text(double t) {
  char text[32];
  const double a = std::abs(t);
  std::snprintf(text, sizeof text, "%s%d:%06.3f", t < 0 ? "-" : "", static_cast<int>(a / 60),
                std::fmod(a, 60.0));
  return text;
}

struct TimeAxis {
  float x0 = 0, x1 = 0;
  double start_s = 0, length_s = 1;
  float x(double t) const { return x0 + static_cast<float>((t - start_s) / length_s) * (x1 - x0); }
  double t(float px) const {
    return start_s + static_cast<double>((px - x0) / (x1 - x0)) * length_s;
  }
  bool visible(double t0, double t1) const { return t1 >= start_s && t0 <= start_s + length_s; }
};

void draw_transport(Session& session, UiState& ui, UiRequests& out) {
  const ImVec2 display = ImGui::GetIO().DisplaySize;
  ImGui::SetNextWindowPos(ImVec2(0, 0));
  ImGui::SetNextWindowSize(ImVec2(display.x, kTransportHeight));
  ImGui::Begin("Transport", nullptr, kPanelFlags | ImGuiWindowFlags_NoTitleBar);
  if (ImGui::Button(ui.playing ? "Pause" : "Play")) out.toggle_play = true;
  record(ui, "transport/play");
  ImGui::SameLine();
  if (ImGui::Button("|<")) out.seek_s = session.timeline().start_s;
  ImGui::SameLine();
  ImGui::Text("%s", clock_text(ui.time_s).c_str());
  ImGui::SameLine();
  ImGui::SetNextItemWidth(90);
  float tempo = static_cast<float>(ui.tempo);
  if (ImGui::SliderFloat("tempo", &tempo, static_cast<float>(runtime::kMinTempo),
                         static_cast<float>(runtime::kMaxTempo), "%.2fx",
                         ImGuiSliderFlags_Logarithmic)) {
    out.tempo = tempo;
  }
  ImGui::SameLine();
  const Document& doc = session.document();
  if (ImGui::Button("Undo")) request(ui, PendingAction::Kind::undo);
  record(ui, "transport/undo");
  if (ImGui::IsItemHovered() && doc.can_undo()) ImGui::SetTooltip("%s", doc.undo_label().c_str());
  ImGui::SameLine();
  if (ImGui::Button("Redo")) request(ui, PendingAction::Kind::redo);
  record(ui, "transport/redo");
  ImGui::SameLine();
  if (ImGui::Button(doc.dirty() ? "Save*" : "Save")) {
    Status s = session.document().save();
    ui.status = s ? "saved " + doc.path().filename().string() : s.error().message;
  }
  record(ui, "transport/save");
  ImGui::SameLine();
  ImGui::TextUnformatted(ui.status.c_str());
  ImGui::End();
}

void draw_variation(Session& session, UiState& ui, const PlayerRef& player,
                    const scene::Variation& variation, std::uint64_t seed) {
  const ensemble_variation::VariationParams drawn = ensemble_variation::resolve_variation(seed, {});
  for (std::size_t f = 0; f < scene::kVariationFields.size(); ++f) {
    const scene::VariationField& field = scene::kVariationFields[f];
    const std::optional<double>& set = variation.*field.value;
    float value = static_cast<float>(set ? *set : drawn.*kParamOf[f]);
    ImGui::PushID(static_cast<int>(f));
    bool overridden = set.has_value();
    if (ImGui::Checkbox("##set", &overridden)) {
      apply(session, ui,
            set_variation(session.document().json(), player, field.key,
                          overridden ? std::optional<double>(value) : std::nullopt));
    }
    if (ImGui::IsItemHovered()) ImGui::SetTooltip("set here (unticked: from the seed)");
    ImGui::SameLine();
    constexpr float kSliderWidth = 150.0f;
    ImGui::SetNextItemWidth(kSliderWidth);
    const std::string name(field.key);
    const bool changed = ImGui::SliderFloat(name.c_str(), &value, 0.0f, 1.0f, "%.2f");
    record(ui, "inspector/" + name);
    ui.widgets.back().x1 = ui.widgets.back().x0 + kSliderWidth;  // the slider, not its label
    if (ImGui::IsItemHovered()) ImGui::SetTooltip("%s", std::string(field.meaning).c_str());
    if (changed) {
      // While the slider is held, each change replaces the last: one undo step per drag.
      const bool continuing = !ImGui::IsItemActivated() && set.has_value();
      apply(session, ui, set_variation(session.document().json(), player, field.key, value),
            continuing);
    }
    ImGui::PopID();
  }
  ImGui::Text("seed %llu", static_cast<unsigned long long>(seed));
  ImGui::SameLine();
  if (ImGui::Button("Re-roll seed")) {
    apply(session, ui, set_seed(session.document().json(), player, reroll_seed(seed)));
  }
  record(ui, "inspector/reroll");
}

// A fingered player's hands: the allowed positions of each event (bands) and the path through them,
// over the few seconds around the playhead.
void draw_hand_area(const TimelineLane& timeline, const UiState& ui) {
  const ImVec2 origin = ImGui::GetCursorScreenPos();
  const ImVec2 size(kInspectorWidth - 24, 150);
  ImGui::InvisibleButton("hand_area", size);
  ImDrawList* draw = ImGui::GetWindowDrawList();
  draw->AddRectFilled(origin, ImVec2(origin.x + size.x, origin.y + size.y), srgb(20, 22, 28, 255));
  double lo = 1e9, hi = -1e9;
  const double t0 = ui.time_s - 2.0, t1 = ui.time_s + 4.0;
  for (const auto& side : timeline.corridors) {
    for (const HandCorridorView& c : side) {
      if (c.end_s < t0 || c.start_s > t1) continue;
      lo = std::min(lo, c.lo_mm);
      hi = std::max(hi, c.hi_mm);
    }
  }
  if (lo > hi) {
    ImGui::TextUnformatted("no notes near the playhead");
    return;
  }
  lo -= 20;
  hi += 20;
  auto px = [&](double t) { return origin.x + static_cast<float>((t - t0) / (t1 - t0)) * size.x; };
  auto py = [&](double mm) {
    return origin.y + size.y - static_cast<float>((mm - lo) / (hi - lo)) * size.y;
  };
  const ImU32 colours[2] = {srgb(90, 160, 255, 90), srgb(255, 170, 80, 90)};
  for (std::size_t side = 0; side < 2; ++side) {
    for (const HandCorridorView& c : timeline.corridors[side]) {
      if (c.end_s < t0 || c.start_s > t1) continue;
      draw->AddRectFilled(ImVec2(px(c.start_s), py(c.hi_mm)), ImVec2(px(c.end_s), py(c.lo_mm)),
                          colours[side]);
    }
  }
  const ImU32 path_colours[2] = {srgb(150, 200, 255), srgb(255, 200, 140)};
  for (std::size_t side = 0; side < 2; ++side) {
    const auto& path = timeline.hand_path[side];
    const auto first =
        std::lower_bound(path.begin(), path.end(), t0,
                         [](const std::array<double, 2>& p, double t) { return p[0] < t; });
    for (auto it = first; it != path.end() && it + 1 != path.end() && (*it)[0] < t1; ++it) {
      draw->AddLine(ImVec2(px((*it)[0]), py((*it)[1])),
                    ImVec2(px((*(it + 1))[0]), py((*(it + 1))[1])), path_colours[side], 2.0f);
    }
  }
  draw->AddLine(ImVec2(px(ui.time_s), origin.y), ImVec2(px(ui.time_s), origin.y + size.y),
                srgb(255, 255, 255, 160));
  ImGui::TextUnformatted("allowed hand positions and the path: right blue, left orange");
}

void draw_inspector(Session& session, UiState& ui) {
  const ImVec2 display = ImGui::GetIO().DisplaySize;
  ImGui::SetNextWindowPos(ImVec2(display.x - kInspectorWidth, kTransportHeight));
  ImGui::SetNextWindowSize(
      ImVec2(kInspectorWidth, std::max(100.0f, display.y - kTransportHeight - kTimelineHeight)));
  ImGui::Begin("Inspector", nullptr, kPanelFlags);
  const Timeline& timeline = session.timeline();
  if (timeline.lanes.empty()) {
    ImGui::End();
    return;
  }
  ui.selected_lane = std::min(ui.selected_lane, timeline.lanes.size() - 1);
  const TimelineLane& lane = timeline.lanes[ui.selected_lane];
  const PlayerRef player{lane.player, lane.name};
  ImGui::Text("%s", lane.name.c_str());
  if (!lane.summary.empty()) ImGui::Text("%s", lane.summary.c_str());
  if (lane.fingered) {
    ImGui::TextUnformatted("Click a note on the timeline to pin a finger.");
    for (const stage::PinView& pin : lane.pins) {
      ImGui::PushID(&pin);
      ImGui::Text("key %d at %.3f s: finger %d", pin.key, pin.time_s, pin.finger);
      ImGui::SameLine();
      const stage::PinView copy = pin;
      if (ImGui::SmallButton("unpin")) {
        ImGui::PopID();
        apply(session, ui, unpin_finger(session.document().json(), player, copy.time_s, copy.key));
        break;
      }
      ImGui::PopID();
    }
    ImGui::Separator();
    draw_hand_area(lane, ui);
  }
  ImGui::Separator();
  draw_variation(session, ui, player, lane.variation, lane.seed);
  if (lane.expressive) {
    ImGui::Separator();
    ImGui::TextUnformatted("Expressions (right-click the lane to add)");
    for (std::size_t i = 0; i < lane.expressions.size(); ++i) {
      const scene::Expression e = lane.expressions[i];
      ImGui::PushID(static_cast<int>(i));
      ImGui::Text("%s %.2f-%.2f s (%.2f)", std::string(scene::expression_name(e.kind)).c_str(),
                  e.start_s, e.end_s, e.amount);
      ImGui::SameLine();
      if (ImGui::SmallButton("delete")) {
        apply(session, ui, delete_expression(session.document().json(), player, e));
      }
      ImGui::PopID();
    }
  }
  ImGui::End();
}

// The nearest time in `times` to px within the grab distance, or -1.
int grab(const TimeAxis& axis, const std::vector<double>& times, float px) {
  int best = -1;
  float best_distance = kGrabPixels;
  for (std::size_t i = 0; i < times.size(); ++i) {
    const float d = std::abs(axis.x(times[i]) - px);
    if (d <= best_distance) {
      best = static_cast<int>(i);
      best_distance = d;
    }
  }
  return best;
}

enum DragKind { kDragShot = 0, kDragCue = 1, kDragBreath = 2, kDragExpression = 3 };

void draw_timeline(Session& session, UiState& ui, UiRequests& out) {
  const ImVec2 display = ImGui::GetIO().DisplaySize;
  ImGui::SetNextWindowPos(ImVec2(0, display.y - kTimelineHeight));
  ImGui::SetNextWindowSize(ImVec2(display.x, kTimelineHeight));
  ImGui::Begin("Timeline", nullptr, kPanelFlags);
  const Timeline& timeline = session.timeline();
  const scene::Scene& scene = session.document().scene();
  const ImGuiIO& io = ImGui::GetIO();

  float view_start = static_cast<float>(ui.view_start_s);
  ImGui::SetNextItemWidth(260);
  ImGui::SliderFloat("view from", &view_start, static_cast<float>(timeline.start_s),
                     static_cast<float>(std::max(timeline.start_s, timeline.end_s - 5.0)),
                     "%.1f s");
  ui.view_start_s = view_start;
  ImGui::SameLine();
  float length = static_cast<float>(ui.view_length_s);
  ImGui::SetNextItemWidth(160);
  ImGui::SliderFloat("span", &length, 4.0f, 60.0f, "%.0f s");
  ui.view_length_s = length;

  const ImVec2 origin = ImGui::GetCursorScreenPos();
  const float width = ImGui::GetContentRegionAvail().x;
  TimeAxis axis;
  axis.x0 = origin.x + kLabelWidth;
  axis.x1 = origin.x + width;
  axis.start_s = ui.view_start_s;
  axis.length_s = ui.view_length_s;
  ImDrawList* draw = ImGui::GetWindowDrawList();
  const double mouse_t = axis.t(io.MousePos.x);
  const double snapped_t = snap_to_beat(timeline, mouse_t, axis.length_s / 150.0);

  // Ruler: bars numbered, beats ticked; click or drag to scrub.
  float y = origin.y;
  ImGui::SetCursorScreenPos(ImVec2(axis.x0, y));
  ImGui::InvisibleButton("ruler", ImVec2(axis.x1 - axis.x0, kRulerHeight));
  record(ui, "timeline/ruler");
  if (ImGui::IsItemActive()) out.seek_s = std::clamp(mouse_t, timeline.start_s, timeline.end_s);
  draw->AddRectFilled(ImVec2(axis.x0, y), ImVec2(axis.x1, y + kRulerHeight), srgb(40, 42, 50, 255));
  for (double t : timeline.beats_s) {
    if (!axis.visible(t, t)) continue;
    draw->AddLine(ImVec2(axis.x(t), y + kRulerHeight - 5), ImVec2(axis.x(t), y + kRulerHeight),
                  srgb(150, 150, 150, 255));
  }
  for (std::size_t b = 0; b < timeline.bars_s.size(); ++b) {
    const double t = timeline.bars_s[b];
    if (!axis.visible(t, t)) continue;
    draw->AddLine(ImVec2(axis.x(t), y), ImVec2(axis.x(t), y + kRulerHeight),
                  srgb(220, 220, 220, 255));
    draw->AddText(ImVec2(axis.x(t) + 3, y + 2), srgb(220, 220, 220, 255),
                  std::to_string(b + 1).c_str());
  }
  y += kRulerHeight + 2;

  // Camera cuts.
  draw->AddText(ImVec2(origin.x, y + 2), srgb(200, 200, 200, 255), "cameras");
  ImGui::SetCursorScreenPos(ImVec2(axis.x0, y));
  ImGui::InvisibleButton("cameras", ImVec2(axis.x1 - axis.x0, kRowHeight));
  record(ui, "timeline/cameras");
  std::vector<double> shot_times;
  for (const auto& shot : timeline.shots) shot_times.push_back(shot.start_s);
  for (std::size_t i = 0; i < timeline.shots.size(); ++i) {
    const double t0 = timeline.shots[i].start_s;
    const double t1 =
        i + 1 < timeline.shots.size() ? timeline.shots[i + 1].start_s : timeline.end_s;
    if (!axis.visible(t0, t1)) continue;
    const bool selected = ui.selection == UiState::Selection::shot && ui.selected_index == i;
    const ImU32 fill = srgb(60 + static_cast<int>(i % 4) * 30, 70, 110, 255);
    draw->AddRectFilled(ImVec2(std::max(axis.x0, axis.x(t0)), y),
                        ImVec2(std::min(axis.x1, axis.x(t1)), y + kRowHeight), fill);
    if (selected) {
      draw->AddRect(ImVec2(axis.x(t0), y), ImVec2(axis.x(t1), y + kRowHeight),
                    srgb(255, 230, 0, 255));
    }
    draw->AddText(ImVec2(std::max(axis.x0, axis.x(t0)) + 3, y + 3), srgb(255, 255, 255, 255),
                  timeline.shots[i].camera.c_str());
  }
  if (ImGui::IsItemClicked(ImGuiMouseButton_Left)) {
    const int i = grab(axis, shot_times, io.MousePos.x);
    if (i > 0) {
      ui.selection = UiState::Selection::shot;
      ui.selected_index = static_cast<std::size_t>(i);
      ui.drag_kind = kDragShot;
      ui.drag_index = static_cast<std::size_t>(i);
      ui.drag_from_s = shot_times[static_cast<std::size_t>(i)];
    } else {
      ui.selection = UiState::Selection::shot;
      ui.selected_index = scene.shot_at(mouse_t);
    }
  }
  if (ImGui::IsItemClicked(ImGuiMouseButton_Right)) ui.context_s = snapped_t;
  if (ImGui::BeginPopupContextItem("cut_popup")) {
    for (const scene::Camera& camera : scene.cameras) {
      if (ImGui::MenuItem(("Cut to " + camera.name + " here").c_str())) {
        apply(session, ui, add_shot(session.document().json(), camera.name, ui.context_s));
      }
    }
    ImGui::EndPopup();
  }
  y += kRowHeight + 2;

  // The lead's cues.
  draw->AddText(ImVec2(origin.x, y + 2), srgb(200, 200, 200, 255),
                timeline.cues_automatic ? "cues (auto)" : "cues");
  ImGui::SetCursorScreenPos(ImVec2(axis.x0, y));
  ImGui::InvisibleButton("cues", ImVec2(axis.x1 - axis.x0, kRowHeight));
  record(ui, "timeline/cues");
  for (std::size_t i = 0; i < timeline.cues_s.size(); ++i) {
    const double t = timeline.cues_s[i];
    if (!axis.visible(t, t)) continue;
    const float x = axis.x(t);
    const bool selected = ui.selection == UiState::Selection::cue && ui.selected_index == i;
    draw->AddTriangleFilled(ImVec2(x, y + 2), ImVec2(x - 6, y + kRowHeight - 2),
                            ImVec2(x + 6, y + kRowHeight - 2),
                            selected ? srgb(255, 230, 0, 255) : srgb(230, 120, 60, 255));
  }
  if (ImGui::IsItemClicked(ImGuiMouseButton_Left)) {
    const int i = grab(axis, timeline.cues_s, io.MousePos.x);
    if (i >= 0) {
      ui.selection = UiState::Selection::cue;
      ui.selected_index = static_cast<std::size_t>(i);
      ui.drag_kind = kDragCue;
      ui.drag_index = static_cast<std::size_t>(i);
      ui.drag_from_s = timeline.cues_s[static_cast<std::size_t>(i)];
    }
  }
  if (ImGui::IsItemClicked(ImGuiMouseButton_Right)) ui.context_s = snapped_t;
  if (ImGui::BeginPopupContextItem("cue_popup")) {
    if (ImGui::MenuItem("Cue here")) {
      apply(session, ui, add_cue(session.document().json(), timeline.cues_s, ui.context_s));
    }
    ImGui::EndPopup();
  }
  y += kRowHeight + 2;

  // One lane per player.
  for (std::size_t l = 0; l < timeline.lanes.size(); ++l) {
    const TimelineLane& lane = timeline.lanes[l];
    const PlayerRef player{lane.player, lane.name};
    ImGui::PushID(static_cast<int>(l));
    const bool selected_lane = ui.selected_lane == l;
    draw->AddText(ImVec2(origin.x, y + 2),
                  selected_lane ? srgb(255, 230, 0, 255) : srgb(200, 200, 200, 255),
                  lane.name.c_str());
    ImGui::SetCursorScreenPos(ImVec2(axis.x0, y));
    ImGui::InvisibleButton("lane", ImVec2(axis.x1 - axis.x0, kLaneHeight));
    record(ui, "timeline/lane/" + lane.name);
    draw->AddRectFilled(ImVec2(axis.x0, y), ImVec2(axis.x1, y + kLaneHeight),
                        selected_lane ? srgb(34, 36, 44, 255) : srgb(26, 27, 32, 255));
    for (const scene::Expression& e : lane.expressions) {
      if (!axis.visible(e.start_s, e.end_s)) continue;
      const ImU32 colour =
          e.kind == scene::ExpressionKind::strain ? srgb(200, 60, 60, 90) : srgb(60, 180, 90, 90);
      draw->AddRectFilled(ImVec2(std::max(axis.x0, axis.x(e.start_s)), y),
                          ImVec2(std::min(axis.x1, axis.x(e.end_s)), y + kLaneHeight), colour);
    }
    const int span = std::max(1, lane.highest_key - lane.lowest_key);
    int hovered_note = -1;
    for (std::size_t n = 0; n < lane.notes.size(); ++n) {
      const TimelineNote& note = lane.notes[n];
      if (!axis.visible(note.start_s, note.end_s)) continue;
      const float ny = y + kLaneHeight - 4 -
                       static_cast<float>(note.key - lane.lowest_key) / static_cast<float>(span) *
                           (kLaneHeight - 10);
      const ImVec2 a(std::max(axis.x0, axis.x(note.start_s)), ny - 3);
      const ImVec2 b(std::min(axis.x1, std::max(axis.x(note.end_s), a.x + 2)), ny + 2);
      ImU32 colour = note.playable ? srgb(200, 200, 210, 255) : srgb(200, 80, 80, 255);
      if (lane.fingered)
        colour = note.right_hand ? srgb(120, 180, 255, 255) : srgb(255, 180, 100, 255);
      if (note.foot >= 0) colour = srgb(130, 210, 130, 255);  // played by a foot
      if (note.pinned) colour = srgb(255, 230, 0, 255);
      draw->AddRectFilled(a, b, colour);
      if (lane.fingered && b.x - a.x > 9 && note.finger > 0) {
        draw->AddText(ImVec2(a.x + 1, ny - 14), srgb(255, 255, 255, 220),
                      std::to_string(note.finger).c_str());
      } else if (b.x - a.x > 9 && note.foot >= 0) {
        draw->AddText(ImVec2(a.x + 1, ny - 14), srgb(255, 255, 255, 220),
                      note.foot == 0 ? "R" : "L");
      }
      if (io.MousePos.x >= a.x && io.MousePos.x <= b.x && io.MousePos.y >= a.y - 4 &&
          io.MousePos.y <= b.y + 4) {
        hovered_note = static_cast<int>(n);
      }
    }
    std::vector<double> breath_ends;
    for (std::size_t b = 0; b < lane.breaths.size(); ++b) {
      const TimelineBreath& breath = lane.breaths[b];
      breath_ends.push_back(breath.boundary_s);
      if (!axis.visible(breath.prepare_s, breath.end_s)) continue;
      const bool selected =
          selected_lane && ui.selection == UiState::Selection::breath && ui.selected_index == b;
      const ImVec2 a(axis.x(breath.start_s), y + 1);
      const ImVec2 c(std::max(axis.x(breath.end_s), a.x + 3), y + kLaneHeight - 1);
      draw->AddRectFilled(a, c,
                          breath.catch_breath ? srgb(80, 140, 255, 110) : srgb(80, 200, 255, 90));
      if (breath.marked || selected) {
        draw->AddRect(a, c, selected ? srgb(255, 230, 0, 255) : srgb(150, 230, 255, 255));
      }
    }
    if (ImGui::IsItemClicked(ImGuiMouseButton_Left)) {
      ui.selected_lane = l;
      ui.selection = UiState::Selection::none;
      const int b = grab(axis, breath_ends, io.MousePos.x);
      int inside = -1;
      for (std::size_t i = 0; i < lane.breaths.size(); ++i) {
        if (mouse_t >= lane.breaths[i].start_s && mouse_t <= lane.breaths[i].boundary_s) {
          inside = static_cast<int>(i);
        }
      }
      const int picked = b >= 0 ? b : inside;
      if (lane.fingered && hovered_note >= 0) {
        ui.pin_note = static_cast<std::size_t>(hovered_note);
        ImGui::OpenPopup("pin_popup");
      } else if (picked >= 0 && lane.breathes) {
        ui.selection = UiState::Selection::breath;
        ui.selected_index = static_cast<std::size_t>(picked);
        ui.drag_kind = kDragBreath;
        ui.drag_index = static_cast<std::size_t>(picked);
        ui.drag_from_s = lane.breaths[static_cast<std::size_t>(picked)].boundary_s;
        ui.drag_marked = lane.breaths[static_cast<std::size_t>(picked)].marked;
      } else {
        for (std::size_t i = 0; i < lane.expressions.size(); ++i) {
          if (mouse_t >= lane.expressions[i].start_s && mouse_t <= lane.expressions[i].end_s) {
            ui.selection = UiState::Selection::expression;
            ui.selected_index = i;
            ui.drag_kind = kDragExpression;
            ui.drag_index = i;
            ui.drag_from_s = mouse_t;
          }
        }
      }
    }
    if (ImGui::IsItemClicked(ImGuiMouseButton_Right)) ui.context_s = snapped_t;
    if ((lane.breathes || lane.expressive) && ImGui::BeginPopupContextItem("lane_popup")) {
      const double bar =
          timeline.beats_s.size() > 4 ? 4 * (timeline.beats_s[1] - timeline.beats_s[0]) : 2.0;
      if (lane.breathes) {
        const bool breathe = ImGui::MenuItem("Breathe here");
        record(ui, "lane_popup/breathe");
        if (breathe) {
          apply(session, ui,
                add_breath(session.document().json(), player,
                           session.breath_boundary(player, ui.context_s)));
        }
      }
      if (lane.expressive && ImGui::MenuItem("Strain from here (one bar)")) {
        apply(
            session, ui,
            add_expression(session.document().json(), player,
                           {scene::ExpressionKind::strain, ui.context_s, ui.context_s + bar, 1.0}));
      }
      if (lane.expressive && ImGui::MenuItem("Relaxed from here (one bar)")) {
        apply(session, ui,
              add_expression(
                  session.document().json(), player,
                  {scene::ExpressionKind::relaxed, ui.context_s, ui.context_s + bar, 1.0}));
      }
      ImGui::EndPopup();
    }
    if (lane.fingered && ImGui::BeginPopup("pin_popup")) {
      if (ui.pin_note < lane.notes.size()) {
        const TimelineNote note = lane.notes[ui.pin_note];
        if (note.foot >= 0) {
          ImGui::Text("pedal %d at %.3f s: the %s foot", note.key, note.start_s,
                      note.foot == 0 ? "right" : "left");
        } else {
          ImGui::Text("key %d at %.3f s (finger %d%s)", note.key, note.start_s, note.finger,
                      note.pinned ? ", pinned" : "");
        }
        for (int f = 1; f <= 5 && note.foot < 0; ++f) {
          if (f > 1) ImGui::SameLine();
          if (ImGui::Button(std::to_string(f).c_str())) {
            apply(session, ui,
                  pin_finger(session.document().json(), player, note.start_s, note.key, f));
            ImGui::CloseCurrentPopup();
          }
        }
        if (note.pinned && ImGui::Button("Unpin")) {
          apply(session, ui,
                unpin_finger(session.document().json(), player, note.start_s, note.key));
          ImGui::CloseCurrentPopup();
        }
      }
      ImGui::EndPopup();
    }
    ImGui::PopID();
    y += kLaneHeight + 2;
  }

  // The playhead.
  if (axis.visible(ui.time_s, ui.time_s)) {
    draw->AddLine(ImVec2(axis.x(ui.time_s), origin.y), ImVec2(axis.x(ui.time_s), y),
                  srgb(255, 80, 80, 255), 2.0f);
  }

  // A drag ends: move what was grabbed to where it was let go (snapped to the beat).
  if (ui.drag_kind >= 0 && ImGui::IsMouseReleased(ImGuiMouseButton_Left)) {
    const double to = snapped_t;
    if (std::abs(axis.x(to) - axis.x(ui.drag_from_s)) > 3.0f) {
      if (ui.drag_kind == kDragShot) {
        apply(session, ui, move_shot(session.document().json(), ui.drag_index, to));
      } else if (ui.drag_kind == kDragCue) {
        apply(session, ui, move_cue(session.document().json(), timeline.cues_s, ui.drag_index, to));
      } else if (ui.drag_kind == kDragExpression && ui.selected_lane < timeline.lanes.size() &&
                 ui.drag_index < timeline.lanes[ui.selected_lane].expressions.size()) {
        // The span moves with the pointer; its start lands on a beat when near one.
        const TimelineLane& lane = timeline.lanes[ui.selected_lane];
        const scene::Expression& e = lane.expressions[ui.drag_index];
        const double start =
            snap_to_beat(timeline, e.start_s + (mouse_t - ui.drag_from_s), axis.length_s / 150.0);
        apply(session, ui,
              move_expression(session.document().json(), PlayerRef{lane.player, lane.name}, e,
                              start));
      } else if (ui.drag_kind == kDragBreath && ui.selected_lane < timeline.lanes.size()) {
        const TimelineLane& lane = timeline.lanes[ui.selected_lane];
        const PlayerRef player{lane.player, lane.name};
        apply(session, ui,
              move_breath(session.document().json(), player, ui.drag_from_s, ui.drag_marked,
                          session.breath_boundary(player, to)));
      }
      ui.selection = UiState::Selection::none;
    }
    ui.drag_kind = -1;
  }
  ImGui::End();
}

void delete_selection(Session& session, UiState& ui) {
  const Timeline& timeline = session.timeline();
  const Json& json = session.document().json();
  switch (ui.selection) {
    case UiState::Selection::breath: {
      const TimelineLane& lane = timeline.lanes[ui.selected_lane];
      if (ui.selected_index < lane.breaths.size()) {
        apply(session, ui,
              delete_breath(json, PlayerRef{lane.player, lane.name},
                            lane.breaths[ui.selected_index].boundary_s,
                            lane.breaths[ui.selected_index].marked));
      }
      break;
    }
    case UiState::Selection::cue:
      apply(session, ui, delete_cue(json, timeline.cues_s, ui.selected_index));
      break;
    case UiState::Selection::shot:
      apply(session, ui, delete_shot(json, ui.selected_index));
      break;
    case UiState::Selection::expression: {
      const TimelineLane& lane = timeline.lanes[ui.selected_lane];
      if (ui.selected_index < lane.expressions.size()) {
        apply(session, ui,
              delete_expression(json, PlayerRef{lane.player, lane.name},
                                lane.expressions[ui.selected_index]));
      }
      break;
    }
    case UiState::Selection::none:
      break;
  }
  ui.selection = UiState::Selection::none;
}

void handle_keys(Session& session, UiState& ui, UiRequests& out) {
  const ImGuiIO& io = ImGui::GetIO();
  if (io.WantTextInput) return;
  if (ImGui::IsKeyPressed(ImGui::GetKeyIndex(ImGuiKey_Delete), false))
    delete_selection(session, ui);
  if (ImGui::IsKeyPressed(ImGui::GetKeyIndex(ImGuiKey_Space), false)) out.toggle_play = true;
  if (io.KeyCtrl && ImGui::IsKeyPressed(ImGui::GetKeyIndex(ImGuiKey_Z), false)) {
    request(ui, io.KeyShift ? PendingAction::Kind::redo : PendingAction::Kind::undo);
  }
  if (io.KeyCtrl && ImGui::IsKeyPressed(ImGui::GetKeyIndex(ImGuiKey_Y), false)) {
    request(ui, PendingAction::Kind::redo);
  }
}

void draw_prompts(Session& session, UiState& ui, UiRequests& out) {
  if (ui.offer_recovery) {
    ImGui::OpenPopup("Recover unsaved changes?");
    ui.offer_recovery = false;
  }
  if (ImGui::BeginPopupModal("Recover unsaved changes?", nullptr,
                             ImGuiWindowFlags_AlwaysAutoResize)) {
    ImGui::TextUnformatted("The autosave has edits that were never saved.");
    if (ImGui::Button("Recover")) {
      request(ui, PendingAction::Kind::recover);
      ImGui::CloseCurrentPopup();
    }
    ImGui::SameLine();
    if (ImGui::Button("Keep the saved file")) ImGui::CloseCurrentPopup();
    ImGui::EndPopup();
  }
  if (ui.quit_requested) {
    ui.quit_requested = false;
    if (!session.document().dirty()) {
      out.quit = true;
    } else {
      ImGui::OpenPopup("Unsaved changes");
    }
  }
  if (ImGui::BeginPopupModal("Unsaved changes", nullptr, ImGuiWindowFlags_AlwaysAutoResize)) {
    ImGui::Text("%s has unsaved changes.", session.document().path().filename().string().c_str());
    if (ImGui::Button("Save and quit")) {
      Status s = session.document().save();
      if (s) {
        out.quit = true;
      } else {
        ui.status = s.error().message;
      }
      ImGui::CloseCurrentPopup();
    }
    record(ui, "prompt/save");
    ImGui::SameLine();
    if (ImGui::Button("Discard and quit")) {
      session.document().discard_autosave();
      out.quit = true;
      ImGui::CloseCurrentPopup();
    }
    record(ui, "prompt/discard");
    ImGui::SameLine();
    if (ImGui::Button("Cancel")) ImGui::CloseCurrentPopup();
    record(ui, "prompt/cancel");
    ImGui::EndPopup();
  }
}

}  // namespace

UiRequests draw_editor(Session& session, UiState& ui) {
  UiRequests out;
  ui.widgets.clear();
  draw_transport(session, ui, out);
  draw_inspector(session, ui);
  draw_timeline(session, ui, out);
  handle_keys(session, ui, out);
  draw_prompts(session, ui, out);
  run_pending(session, ui);
  return out;
}

const WidgetBox* find_widget(const UiState& ui, const std::string& id) {
  for (const WidgetBox& box : ui.widgets) {
    if (box.id == id) return &box;
  }
  return nullptr;
}

}  // namespace tutti::editor
