// SPDX-License-Identifier: MIT
#include <tutti/cli/play_command.hpp>

#include <dlfcn.h>
#define GLFW_INCLUDE_NONE
#include <GLFW/glfw3.h>

#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <functional>
#include <memory>
#include <optional>
#include <ostream>
#include <vector>

#include <tutti/core/exit_codes.hpp>
#include <tutti/cli/stage_scene.hpp>
#include <tutti/performance/draft_scene.hpp>
#include <tutti/cli/play_live.hpp>
#include <tutti/cli/size_option.hpp>
#include <tutti/image/png.hpp>
#include <tutti/render/frame_target.hpp>
#include <tutti/render/vulkan_context.hpp>
#include <tutti/render/window.hpp>
#include <tutti/render/window_target.hpp>
#include <tutti/runtime/dynamic_resolution.hpp>
#include <tutti/runtime/imgui_layer.hpp>
#include <tutti/runtime/input_bindings.hpp>
#include <tutti/runtime/scene_player.hpp>
#include <tutti/runtime/view_stats.hpp>
#include <tutti/scene/load_scene.hpp>

namespace tutti::cli {
namespace {

// A whole string as a finite number (seconds, a scale); nullopt otherwise.
std::optional<double> parse_number(const std::string& text) {
  if (text.empty()) return std::nullopt;
  char* end = nullptr;
  const double value = std::strtod(text.c_str(), &end);
  if (end != text.c_str() + text.size() || !std::isfinite(value)) return std::nullopt;
  return value;
}

// Without a sound card ALSA prints its own errors to stderr while FluidSynth looks for a device
// ("ALSA lib pcm.c:...: Unknown PCM default"); the one-line notice after it says it better.
// libasound is loaded with FluidSynth already; found through dlsym, so tutti needs no ALSA
// headers (and nothing happens without it).
void ignore_alsa_error(const char*, int, const char*, int, const char*, ...) {}

void quiet_alsa_errors() {
  using Handler = void (*)(const char*, int, const char*, int, const char*, ...);
  using SetHandler = int (*)(Handler);
  void* symbol = dlsym(RTLD_DEFAULT, "snd_lib_error_set_handler");
  if (symbol == nullptr) return;
  reinterpret_cast<SetHandler>(symbol)(ignore_alsa_error);
}

// GLFW's callbacks, turned into actions for the main loop (GLFW calls them from poll_events).
struct InputQueue {
  std::vector<runtime::Action> actions;
  live::KeyboardPiano* piano = nullptr;  // --keyboard-piano: its keys go to it first
  std::function<double()> clock;
  bool dragging = false;
  int button = -1;
  int mods = 0;
  double last_x = 0.0, last_y = 0.0;

  static InputQueue& of(GLFWwindow* window) {
    return *static_cast<InputQueue*>(glfwGetWindowUserPointer(window));
  }
  void install(GLFWwindow* window) {
    glfwSetWindowUserPointer(window, this);
    glfwSetKeyCallback(window, [](GLFWwindow* w, int key, int, int action, int key_mods) {
      InputQueue& q = of(w);
      if (q.piano != nullptr && action != GLFW_REPEAT) {
        const bool taken = action == GLFW_PRESS ? q.piano->press(key, q.clock())
                                                : q.piano->release(key, q.clock());
        if (taken) return;
      }
      if (action == GLFW_PRESS ||
          (action == GLFW_REPEAT && (key == GLFW_KEY_LEFT || key == GLFW_KEY_RIGHT))) {
        const runtime::Action a = runtime::key_action(key, key_mods);
        if (a.kind != runtime::ActionKind::none) of(w).actions.push_back(a);
      }
    });
    glfwSetMouseButtonCallback(window, [](GLFWwindow* w, int pressed, int action, int key_mods) {
      InputQueue& q = of(w);
      if (action == GLFW_PRESS && !q.dragging) {
        q.dragging = true;
        q.button = pressed;
        q.mods = key_mods;
        glfwGetCursorPos(w, &q.last_x, &q.last_y);
      } else if (action == GLFW_RELEASE && pressed == q.button) {
        q.dragging = false;
      }
    });
    glfwSetCursorPosCallback(window, [](GLFWwindow* w, double x, double y) {
      InputQueue& q = of(w);
      if (!q.dragging) return;
      const runtime::Action a = runtime::drag_action(
          q.button, q.mods, static_cast<float>(x - q.last_x), static_cast<float>(y - q.last_y));
      q.last_x = x;
      q.last_y = y;
      if (a.kind != runtime::ActionKind::none) q.actions.push_back(a);
    });
    glfwSetScrollCallback(window, [](GLFWwindow* w, double, double y) {
      const runtime::Action a = runtime::scroll_action(y);
      if (a.kind != runtime::ActionKind::none) of(w).actions.push_back(a);
    });
  }
};

}  // namespace

int run_play(const PlayOptions& o, std::ostream& out, std::ostream& err) {
  const Fail fail{err};
  // Everything that can be checked without a window is checked first.
  if (!(o.tempo >= runtime::kMinTempo && o.tempo <= runtime::kMaxTempo)) {
    char text[96];
    std::snprintf(text, sizeof text, "--tempo %g: must be in [%g, %g]", o.tempo, runtime::kMinTempo,
                  runtime::kMaxTempo);
    return fail(text);
  }
  Size window_size;
  if (!o.size.empty()) {
    auto size = parse_size_option(o.size, 320, 240, /*even=*/false);
    if (!size) return fail(size.error());
    window_size = *size;
  }
  if (o.quality != "auto" && o.quality != "draft" && o.quality != "full") {
    return fail("--quality \"" + o.quality + "\": must be auto, draft or full");
  }
  std::optional<float> fixed_scale;
  if (o.render_scale != "auto") {
    const std::optional<double> scale = parse_number(o.render_scale);
    if (!scale || *scale < 0.25 || *scale > 1.0) {
      return fail("--render-scale \"" + o.render_scale + "\": must be auto or in [0.25, 1]");
    }
    fixed_scale = static_cast<float>(*scale);
  }
  if (o.frames < 0) {
    return fail("--frame-count " + std::to_string(o.frames) + ": must be 1 or more");
  }
  if (!o.screenshot.empty() && o.screenshot.extension() != ".png") {
    return fail("--screenshot " + o.screenshot.string() + ": writes a .png file");
  }
  std::optional<double> start;
  if (!o.start.empty()) {
    start = parse_number(o.start);
    if (!start) return fail("--start \"" + o.start + "\" is not a time in seconds");
  }
  std::optional<runtime::LoopRange> loop;
  if (!o.loop.empty()) {
    const std::size_t colon = o.loop.find(':');
    const std::optional<double> a =
        colon == std::string::npos ? std::nullopt : parse_number(o.loop.substr(0, colon));
    const std::optional<double> b =
        colon == std::string::npos ? std::nullopt : parse_number(o.loop.substr(colon + 1));
    if (!a || !b || !(*b > *a)) {
      return fail("--loop \"" + o.loop + "\": expected A:B, seconds, A < B");
    }
    loop = runtime::LoopRange{*a, *b};
  }
  std::vector<std::string> draft_notes;
  auto scene = performance::load_scene_or_music(o.scene, {}, &draft_notes);
  if (!scene) return fail(scene.error());
  for (const std::string& note : draft_notes) err << "note: " << note << "\n";
  auto live_play =
      LivePlay::open({o.midi_in, o.keyboard_piano, o.soundfont, o.audio_driver}, *scene);
  if (!live_play) return fail(live_play.error());
  LivePlay& live = **live_play;
  int fixed_camera = -1;
  if (!o.camera.empty()) {
    fixed_camera = scene->find_camera(o.camera);
    if (fixed_camera < 0) {
      return fail("--camera \"" + o.camera + "\": " + scene->source + " has no such camera");
    }
  }

  render::WindowOptions window_options;
  window_options.width = static_cast<std::uint32_t>(
      window_size.width > 0 ? window_size.width : scene->output.width);
  window_options.height = static_cast<std::uint32_t>(
      window_size.height > 0 ? window_size.height : scene->output.height);
  window_options.title = "tutti play " + o.scene.filename().string();
  auto window = render::Window::create(window_options);
  if (!window) return fail(window.error());
  render::VulkanContextOptions context_options;
  context_options.validation = o.validate;
  context_options.device = o.device;
  render::require_presentation(**window, context_options);
  auto context = render::VulkanContext::create(context_options);
  if (!context) return fail(context.error());
  // Draft on a CPU device: one sample per pixel, hard shadows, the 3D view scaled to hold the
  // frame rate; offline renders (tutti render) keep the scene's quality.
  const bool cpu_device = (*context)->device_info().type == VK_PHYSICAL_DEVICE_TYPE_CPU;
  const runtime::ViewQuality quality =
      o.quality == "full" || (o.quality == "auto" && !cpu_device) ? runtime::ViewQuality::full
                                                                  : runtime::ViewQuality::draft;
  const bool draft = quality == runtime::ViewQuality::draft;
  render::WindowTargetOptions target_options;
  target_options.samples = render::sample_count_flag(draft ? 1 : scene->output.msaa);
  target_options.present_mode = VK_PRESENT_MODE_MAILBOX_KHR;  // never wait for a vertical blank
  auto target = render::WindowTarget::create(**context, **window, target_options);
  if (!target) return fail(target.error());

  if (o.audio_driver.empty()) quiet_alsa_errors();
  runtime::ScenePlayerOptions player_options;
  player_options.stage.asset_dir = o.assets;
  if (draft) {
    player_options.renderer.shadow_taps = 1;
    player_options.renderer.shadow_map_size = 1024;
  }
  player_options.tempo = o.tempo;
  player_options.sound_options.sound_font = o.soundfont;
  player_options.sound_options.driver = o.audio_driver;
  player_options.sound = !live.enabled();  // live: the notes that come in sound, not the score
  auto created = runtime::ScenePlayer::create(**context, **target, *scene, player_options);
  if (!created) return fail(created.error());
  runtime::ScenePlayer& player = **created;
  runtime::Transport& transport = player.transport();
  for (const std::string& note : player.stage().notes()) err << "note: " << note << "\n";
  if (live.enabled()) {
    std::string notice;
    if (Status s = live.attach(player.stage(), player.posed().world(), *scene, notice); !s) {
      return fail(s.error());
    }
    if (!notice.empty()) out << notice << "\n";
    out << live.describe() << "\n";
  }
  if (const audio::LiveOutput* sound = transport.output(); sound && sound->simulated()) {
    if (o.audio_driver != "simulated") {
      out << "play: no sound device: playing silently\n";
    }
  }

  const auto host_origin = std::chrono::steady_clock::now();
  auto host_now = [&] {
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - host_origin).count();
  };
  if (fixed_camera >= 0) (void)player.set_scene_camera(static_cast<std::size_t>(fixed_camera));
  if (start) transport.seek(host_now(), *start);
  if (loop) {
    if (Status s = transport.set_loop(host_now(), loop->from_s, loop->to_s); !s) {
      return fail("--loop \"" + o.loop + "\": " + s.error().message);
    }
  }
  runtime::ImGuiLayerOptions overlay_options;
  overlay_options.install_callbacks = false;  // the statistics take no input
  auto overlay = runtime::ImGuiLayer::create(**context, **window, **target, overlay_options);
  if (!overlay) return fail(overlay.error());
  bool show_stats = o.stats;
  runtime::DynamicResolution resolution;
  const bool dynamic = !fixed_scale && draft;
  (*target)->set_render_scale(fixed_scale ? *fixed_scale : 1.0f);
  double last_frame_end_s = -1.0;
  double last_frame_s = 0.0;

  InputQueue input;
  input.piano = live.keyboard();
  input.clock = host_now;
  input.install((*window)->handle());

  auto resized = [&] {
    const render::Window::Size size = (*window)->framebuffer_size();
    const VkExtent2D extent = (*target)->extent();
    return size.width != extent.width || size.height != extent.height;
  };
  transport.play(host_now());
  const double first_frame_s = host_now();
  std::int64_t frames = 0;
  double last_status_s = -1.0;
  std::string last_status;
  for (;;) {
    (*window)->poll_events();
    const double now = host_now();
    bool quit = (*window)->should_close();
    const float height = static_cast<float>(std::max(1u, (*target)->extent().height));
    for (const runtime::Action& action : input.actions) {
      if (action.kind == runtime::ActionKind::toggle_stats) show_stats = !show_stats;
      if (!player.apply(action, now, height)) quit = true;
    }
    const bool acted = !input.actions.empty();
    input.actions.clear();
    if (quit) break;
    // Paused and nothing asked for: the picture cannot change, so wait for input instead of
    // drawing it again (not with --frame-count, which counts drawn frames).
    if (o.frames == 0 && !live.enabled() && !transport.playing() && !acted && frames > 0 &&
        player.shown_time() == transport.time() && !resized()) {
      glfwWaitEventsTimeout(0.1);
      continue;
    }

    const bool last = o.frames > 0 && frames + 1 == o.frames;
    if (last && !o.screenshot.empty()) (*target)->capture_next_frame();
    if (dynamic && last_frame_s > 0.0) (*target)->set_render_scale(resolution.update(last_frame_s));
    if (show_stats) {
      (*overlay)->new_frame();
      runtime::draw_view_stats({last_frame_s, resolution.average_frame_s(), draft, dynamic},
                               **target);
    }
    auto frame = (*target)->begin_frame();
    if (!frame) return fail(frame.error());
    // The time is read after begin_frame's wait for a free slot: the picture shows the music as
    // late as possible, and however long the last frame took, none is drawn for a stale time.
    if (live.enabled()) {
      // Live: the picture is the host's time, and the pianist has played what came in by then.
      const double live_s = host_now();
      live.frame(player.stage(), player.posed().world(), live_s);
      player.show(live_s);
    } else {
      player.update(host_now());
    }
    if (Status s = player.record(*frame, **target); !s) return fail(s.error());
    if (show_stats) (*overlay)->record_overlay(*frame, **target);
    if (auto id = (*target)->end_frame(); !id) return fail(id.error());
    ++frames;
    // A frame's cost: from the end of the one before to the end of this one (the wait for a free
    // slot included: that is the device's time).
    const double frame_end_s = host_now();
    if (last_frame_end_s >= 0.0) last_frame_s = frame_end_s - last_frame_end_s;
    last_frame_end_s = frame_end_s;
    if (o.validate && (*context)->validation_log()->size() > 0) {
      return fail("Vulkan validation: " + (*context)->validation_log()->messages().front());
    }

    // The title every frame it changes; stdout once a second and on every change of state.
    std::string status = player.status_line();
    if (status != last_status) {
      glfwSetWindowTitle((*window)->handle(), ("tutti play  " + status).c_str());
      const std::string state = status.substr(status.find("  "));  // without the time
      const std::string last_state =
          last_status.empty() ? std::string() : last_status.substr(last_status.find("  "));
      if (state != last_state || now - last_status_s >= 1.0) {
        out << "play: " << status << "\n" << std::flush;
        last_status_s = now;
      }
      last_status = std::move(status);
    }
    if (last) break;
  }
  const double elapsed = host_now() - first_frame_s;

  if (!o.screenshot.empty() && frames > 0 && o.frames > 0) {
    auto captured = (*target)->take_capture();
    if (!captured) return fail(captured.error());
    if (Status s =
            image::write_png(o.screenshot, captured->rgba, captured->width, captured->height);
        !s) {
      return fail(s.error());
    }
    out << "play: wrote " << o.screenshot.string() << " (" << captured->width << "x"
        << captured->height << ")\n";
  }
  char summary[256];
  const VkExtent2D view = (*target)->render_extent();
  std::snprintf(summary, sizeof summary,
                "play: %lld frames in %.2f s (%.1f fps), music %.2f s; %s quality, 3D view at "
                "%.0f %% (%ux%u)%s\n",
                static_cast<long long>(frames), elapsed,
                elapsed > 0 ? static_cast<double>(frames) / elapsed : 0.0, player.shown_time(),
                draft ? "draft" : "full", 100.0 * (*target)->render_scale(), view.width,
                view.height, dynamic ? ", dynamic" : "");
  out << summary;
  return kExitOk;
}

void register_play_command(Commands& commands) {
  auto options = std::make_shared<PlayOptions>();
  Command& command = commands.add(
      "play",
      "Play a scene live in a window with its sound (keys: Space play/pause, Left/Right seek, "
      "Home start, 0 director, 1-9 camera, F or drag free camera, [ ] \\ loop, - = tempo, Esc)");
  command.option("SCENE", options->scene, "scene file, or a .mid / .musicxml / .mxl piece")
      .required();
  command.option("--tempo", options->tempo, "practice tempo, 0.1..4 (0.5 = half speed)");
  command.option("--camera", options->camera, "start on this scene camera (not the shot list)");
  command.option("--start", options->start, "start at this time (seconds of the music)");
  command.option("--loop", options->loop, "A:B, play seconds [A, B) over and over");
  command.option("--soundfont", options->soundfont,
                 "General MIDI .sf2 (default: $TUTTI_SOUNDFONT or the system's)");
  command.option("--assets", options->assets, "folder of the generated .glb assets");
  command.option("--audio-driver", options->audio_driver,
                 "FluidSynth audio driver (pulseaudio, alsa, ...; simulated: none)");
  command.option("--device", options->device, "Vulkan device: index or part of its name");
  command.option("--frame-count", options->frames, "quit after drawing this many frames");
  command.option("--size", options->size, "window size WxH (default: the scene's output size)");
  command.option("--quality", options->quality,
                 "auto (draft on a CPU device), draft (1 sample, hard shadows, dynamic 3D view "
                 "scale) or full");
  command.option("--render-scale", options->render_scale,
                 "the 3D view's share of the window per axis: auto or 0.25..1");
  command.flag("--stats", options->stats, "show the statistics (F3) from the start");
  command.option("--screenshot", options->screenshot, "write the last frame to this .png");
  command.option("--midi-in", options->midi_in,
                 "live MIDI (ALSA sequencer): auto, none, CLIENT:PORT or a client name; the "
                 "pianist plays it");
  command.flag("--keyboard-piano", options->keyboard_piano,
               "the computer keyboard as a piano (A S D ... white, W E T ... black, Z/X octave)");
  command.flag("--validate", options->validate,
               "Vulkan validation layer on; any message is an error");
  command.on_run(
      [options](std::ostream& out, std::ostream& err) { return run_play(*options, out, err); });
}

}  // namespace tutti::cli
