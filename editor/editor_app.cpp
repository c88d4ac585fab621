// SPDX-License-Identifier: MIT
#include <tutti/editor/editor_app.hpp>

#include <GLFW/glfw3.h>
#include <imgui.h>

#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <ostream>

#include <tutti/core/exit_codes.hpp>
#include <tutti/editor/editor_ui.hpp>
#include <tutti/editor/script.hpp>
#include <tutti/editor/session.hpp>
#include <tutti/image/png.hpp>
#include <tutti/render/window.hpp>
#include <tutti/render/window_target.hpp>
#include <tutti/runtime/dynamic_resolution.hpp>
#include <tutti/runtime/imgui_layer.hpp>
#include <tutti/runtime/view_stats.hpp>
#include <tutti/runtime/input_bindings.hpp>
#include <tutti/runtime/scene_player.hpp>

namespace tutti::editor {
namespace {


bool parse_size(const std::string& text, std::uint32_t& width, std::uint32_t& height) {
  unsigned w = 0, h = 0;
  char rest = 0;
  if (std::sscanf(text.c_str(), "%ux%u%c", &w, &h, &rest) != 2) return false;
  if (w < 320 || h < 240 || w > 7680 || h > 4320) return false;
  width = w;
  height = h;
  return true;
}

// The viewport's keys (cameras, seeking, loop, tempo) when the panels do not want the keyboard.
constexpr int kViewportKeys[] = {GLFW_KEY_0,
                                 GLFW_KEY_1,
                                 GLFW_KEY_2,
                                 GLFW_KEY_3,
                                 GLFW_KEY_4,
                                 GLFW_KEY_5,
                                 GLFW_KEY_6,
                                 GLFW_KEY_7,
                                 GLFW_KEY_8,
                                 GLFW_KEY_9,
                                 GLFW_KEY_F,
                                 GLFW_KEY_LEFT,
                                 GLFW_KEY_RIGHT,
                                 GLFW_KEY_HOME,
                                 GLFW_KEY_LEFT_BRACKET,
                                 GLFW_KEY_RIGHT_BRACKET,
                                 GLFW_KEY_BACKSLASH,
                                 GLFW_KEY_MINUS,
                                 GLFW_KEY_EQUAL};

int modifiers(const ImGuiIO& io) {
  return (io.KeyShift ? GLFW_MOD_SHIFT : 0) | (io.KeyCtrl ? GLFW_MOD_CONTROL : 0) |
         (io.KeyAlt ? GLFW_MOD_ALT : 0);
}

class Editor final : public ScriptHost {
 public:
  Editor(const EditorOptions& options, std::ostream& out, std::ostream& err)
      : options_(options), out_(out), err_(err) {}

  int run();

  // ScriptHost
  void seek(double t_s) override { player_->transport().seek(now(), t_s); }
  void set_playing(bool playing) override {
    if (playing) {
      player_->transport().play(now());
    } else {
      player_->transport().pause(now());
    }
  }
  void select(const PlayerRef& player) override {
    const auto& lanes = session_->timeline().lanes;
    for (std::size_t i = 0; i < lanes.size(); ++i) {
      if (lanes[i].player == player.pointer) ui_.selected_lane = i;
    }
  }
  Status draw_frames(int count) override {
    for (int i = 0; i < count; ++i) {
      if (Status s = frame(); !s) return s;
    }
    return Status::success();
  }
  Status screenshot(const std::filesystem::path& png) override {
    target_->capture_next_frame();
    if (Status s = frame(); !s) return s;
    auto captured = target_->take_capture();
    if (!captured) return captured.error();
    if (Status s = image::write_png(png, captured->rgba, captured->width, captured->height); !s) {
      return s;
    }
    out_ << "editor: wrote " << png.string() << " (" << captured->width << "x" << captured->height
         << ")\n";
    return Status::success();
  }

 private:
  double now() const {
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - origin_).count();
  }
  int fail(const Error& error) {
    err_ << "error: " << error.message << "\n";
    return exit_code_of(error);
  }
  Status frame();
  void viewport_input();
  void follow_replans();

  EditorOptions options_;
  std::ostream& out_;
  std::ostream& err_;
  std::chrono::steady_clock::time_point origin_ = std::chrono::steady_clock::now();
  std::unique_ptr<render::Window> window_;
  std::unique_ptr<render::VulkanContext> context_;
  std::unique_ptr<render::WindowTarget> target_;
  std::unique_ptr<Session> session_;
  std::unique_ptr<runtime::ScenePlayer> player_;
  std::unique_ptr<runtime::ImGuiLayer> imgui_;
  UiState ui_;
  std::uint64_t shown_revision_ = 0;
  double last_autosave_s_ = 0.0;
  // Draft view on a CPU device (runtime::ViewQuality): hard shadows, a dynamic 3D view scale.
  bool dynamic_resolution_ = false;
  runtime::DynamicResolution resolution_;
  double last_frame_end_s_ = -1.0;
  double last_frame_s_ = 0.0;
  bool show_stats_ = false;  // F3
  bool quit_ = false;
};

void Editor::follow_replans() {
  if (session_->stage_revision() == shown_revision_) return;
  shown_revision_ = session_->stage_revision();
  if (Status s = player_->use_stage(*context_, *target_, session_->shared_stage(),
                                    session_->models_changed(), now());
      !s) {
    ui_.status = s.error().message;
  }
}

void Editor::viewport_input() {
  const ImGuiIO& io = ImGui::GetIO();
  const float height = static_cast<float>(std::max(1u, target_->extent().height));
  if (!io.WantCaptureMouse) {
    for (int button : {GLFW_MOUSE_BUTTON_LEFT, GLFW_MOUSE_BUTTON_RIGHT, GLFW_MOUSE_BUTTON_MIDDLE}) {
      if (io.MouseDown[button] && (io.MouseDelta.x != 0.0f || io.MouseDelta.y != 0.0f)) {
        player_->apply(
            runtime::drag_action(button, modifiers(io), io.MouseDelta.x, io.MouseDelta.y), now(),
            height);
      }
    }
    if (io.MouseWheel != 0.0f) player_->apply(runtime::scroll_action(io.MouseWheel), now(), height);
  }
  if (!io.WantCaptureKeyboard && !io.WantTextInput) {
    for (int key : kViewportKeys) {
      if (ImGui::IsKeyPressed(key, false)) {
        player_->apply(runtime::key_action(key, modifiers(io)), now(), height);
      }
    }
    if (ImGui::IsKeyPressed(GLFW_KEY_ESCAPE, false)) ui_.quit_requested = true;
    if (ImGui::IsKeyPressed(GLFW_KEY_F3, false)) show_stats_ = !show_stats_;
  }
}

Status Editor::frame() {
  window_->poll_events();
  if (window_->should_close()) {
    // Closing asks first when there are unsaved edits (the prompt decides).
    glfwSetWindowShouldClose(window_->handle(), GLFW_FALSE);
    ui_.quit_requested = true;
  }
  runtime::Transport& transport = player_->transport();
  ui_.time_s = player_->shown_time();
  ui_.playing = transport.playing();
  ui_.tempo = transport.tempo();
  imgui_->new_frame();
  const UiRequests requests = draw_editor(*session_, ui_);
  viewport_input();
  follow_replans();
  if (requests.seek_s) transport.seek(now(), *requests.seek_s);
  if (requests.toggle_play) transport.toggle(now());
  if (requests.tempo) (void)transport.set_tempo(now(), *requests.tempo);
  if (requests.quit) quit_ = true;
  if (show_stats_) {
    runtime::draw_view_stats(
        {last_frame_s_, resolution_.average_frame_s(), dynamic_resolution_, dynamic_resolution_},
        *target_, 1);
  }
  if (dynamic_resolution_ && last_frame_s_ > 0.0) {
    target_->set_render_scale(resolution_.update(last_frame_s_));
  }

  auto recording = target_->begin_frame();
  if (!recording) return recording.error();
  player_->update(now());
  if (Status s = player_->record(*recording, *target_); !s) return s;
  imgui_->record_overlay(*recording, *target_);
  if (auto id = target_->end_frame(); !id) return id.error();
  const double frame_end_s = now();
  if (last_frame_end_s_ >= 0.0) last_frame_s_ = frame_end_s - last_frame_end_s_;
  last_frame_end_s_ = frame_end_s;
  if (options_.validate && context_->validation_log()->size() > 0) {
    return Error{"Vulkan validation: " + context_->validation_log()->messages().front()};
  }
  if (session_->document().dirty() && now() - last_autosave_s_ >= options_.autosave_s) {
    if (Status s = session_->document().autosave(); !s) ui_.status = s.error().message;
    last_autosave_s_ = now();
  }
  return Status::success();
}

int Editor::run() {
  std::uint32_t width = 0, height = 0;
  if (!parse_size(options_.size, width, height)) {
    err_ << "error: --size \"" << options_.size << "\": expected WxH, at least 320x240\n";
    return kExitBadInput;
  }
  std::optional<Script> script;
  if (!options_.script.empty()) {
    auto loaded = load_script(options_.script);
    if (!loaded) {
      err_ << "error: " << loaded.error().message << "\n";
      return kExitBadInput;
    }
    script = std::move(*loaded);
  }
  stage::StageOptions stage_options;
  stage_options.asset_dir = options_.assets;
  auto session = Session::open(options_.scene, stage_options);
  if (!session) {
    err_ << "error: " << session.error().message << "\n";
    return kExitBadInput;
  }
  session_ = std::move(*session);
  if (const char* pause = std::getenv("TUTTI_EDITOR_TEST_SAVE_PAUSE_MS")) {
    session_->document().set_save_pause_ms(std::atoi(pause));
  }
  for (const std::string& note : session_->stage().notes()) err_ << "note: " << note << "\n";

  render::WindowOptions window_options;
  window_options.width = width;
  window_options.height = height;
  window_options.title = "tutti-editor " + options_.scene.filename().string();
  auto window = render::Window::create(window_options);
  if (!window) return fail(window.error());
  window_ = std::move(*window);
  render::VulkanContextOptions context_options;
  context_options.validation = options_.validate;
  render::require_presentation(*window_, context_options);
  auto context = render::VulkanContext::create(context_options);
  if (!context) return fail(context.error());
  context_ = std::move(*context);
  render::WindowTargetOptions target_options;
  target_options.present_mode = VK_PRESENT_MODE_MAILBOX_KHR;
  auto target = render::WindowTarget::create(*context_, *window_, target_options);
  if (!target) return fail(target.error());
  target_ = std::move(*target);

  runtime::ScenePlayerOptions player_options;
  dynamic_resolution_ = context_->device_info().type == VK_PHYSICAL_DEVICE_TYPE_CPU;
  if (dynamic_resolution_) {
    player_options.renderer.shadow_taps = 1;
    player_options.renderer.shadow_map_size = 1024;
  }
  player_options.sound_options.sound_font = options_.soundfont;
  player_options.sound_options.driver = options_.audio_driver;
  auto player =
      runtime::ScenePlayer::create(*context_, *target_, session_->shared_stage(), player_options);
  if (!player) return fail(player.error());
  player_ = std::move(*player);
  if (const audio::LiveOutput* sound = player_->transport().output();
      sound != nullptr && sound->simulated() && options_.audio_driver != "simulated") {
    out_ << "editor: no sound device: playing silently\n";
  }
  shown_revision_ = session_->stage_revision();
  auto imgui = runtime::ImGuiLayer::create(*context_, *window_, *target_);
  if (!imgui) return fail(imgui.error());
  imgui_ = std::move(*imgui);

  ui_.view_start_s = session_->timeline().start_s;
  if (session_->document().autosave_available()) {
    if (script) {
      out_ << "editor: " << Document::autosave_path(session_->document().path()).string()
           << " has unsaved edits from an earlier session (left as it is)\n";
    } else {
      ui_.offer_recovery = true;
    }
  }

  std::size_t next_command = 0;
  while (!quit_) {
    if (Status s = frame(); !s) {
      // Whatever went wrong, unsaved edits stay in the autosave.
      (void)session_->document().autosave();
      return fail(s.error());
    }
    if (!script) continue;
    if (next_command >= script->commands.size()) {
      if (session_->document().dirty()) (void)session_->document().autosave();
      return fail(Error{script->file + ": ended without quit"});
    }
    auto step = run_script_command(*script, script->commands[next_command++], *session_, *this);
    if (!step) {
      (void)session_->document().autosave();
      return fail(step.error());
    }
    const ScriptCommand& done = script->commands[next_command - 1];
    out_ << "editor: " << script->file << ":" << done.line << ": " << done.words[0] << " done\n"
         << std::flush;
    follow_replans();
    if (*step == ScriptStep::quit) break;
  }
  return kExitOk;
}

}  // namespace

int run_editor(const EditorOptions& options, std::ostream& out, std::ostream& err) {
  Editor editor(options, out, err);
  return editor.run();
}

}  // namespace tutti::editor
