// SPDX-License-Identifier: MIT
#include <tutti/cli/render_command.hpp>

#include <unistd.h>

#include <chrono>
#include <cmath>
#include <cstdio>
#include <memory>
#include <ostream>
#include <vector>

#include <tutti/core/exit_codes.hpp>
#include <tutti/cli/frame_range.hpp>
#include <tutti/cli/scene_audio.hpp>
#include <tutti/cli/size_option.hpp>
#include <tutti/cli/slice_tag.hpp>
#include <tutti/cli/stage_scene.hpp>
#include <tutti/performance/draft_scene.hpp>
#include <tutti/cli/video_pipe.hpp>
#include <tutti/audio/wav_file.hpp>
#include <tutti/image/png.hpp>
#include <tutti/render/frame_target.hpp>
#include <tutti/audio_sync/audio_clock.hpp>
#include <tutti/render/model_renderer.hpp>
#include <tutti/render/offscreen_target.hpp>
#include <tutti/render/vulkan_context.hpp>
#include <tutti/runtime/input_bindings.hpp>
#include <tutti/runtime/stage_renderer.hpp>
#include <tutti/runtime/stage_view.hpp>
#include <tutti/scene/load_scene.hpp>
#include <tutti/performance/families.hpp>
#include <tutti/stage/stage.hpp>

namespace tutti::cli {
namespace {

enum class OutputKind { video, png, folder };

Result<OutputKind> output_kind(const RenderOptions& o) {
  const std::string ext = o.output.extension().string();
  if (!o.still.empty()) {
    if (ext != ".png") return Error{o.output.string() + ": --still writes a .png file"};
    return OutputKind::png;
  }
  if (ext == ".mp4") return OutputKind::video;
  if (ext.empty() || o.output.string().back() == '/') return OutputKind::folder;
  return Error{o.output.string() +
               ": the output must be .mp4, a folder for PNG frames, or .png "
               "with --still"};
}

// "[=====>     ] 120/900 frames  34.2 fps  ETA 0:23" on a terminal (redrawn in place), else a
// plain line every 10 %.
class Progress {
 public:
  Progress(std::ostream& err, std::int64_t total, bool enabled)
      : err_(err),
        total_(total),
        enabled_(enabled),
        terminal_(isatty(STDERR_FILENO) != 0),
        start_(std::chrono::steady_clock::now()) {}

  void frame_done(std::int64_t done) {
    if (!enabled_) return;
    const double elapsed =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start_).count();
    const double fps = elapsed > 0 ? static_cast<double>(done) / elapsed : 0.0;
    const double eta = fps > 0 ? static_cast<double>(total_ - done) / fps : 0.0;
    char line[160];
    if (terminal_) {
      const int width = 30;
      const int filled = static_cast<int>(width * done / std::max<std::int64_t>(total_, 1));
      std::string bar(static_cast<std::size_t>(filled), '=');
      if (filled < width) bar += '>';
      bar.resize(width, ' ');
      std::snprintf(line, sizeof line, "\r[%s] %lld/%lld frames  %.1f fps  ETA %d:%02d ",
                    bar.c_str(), static_cast<long long>(done), static_cast<long long>(total_), fps,
                    static_cast<int>(eta) / 60, static_cast<int>(eta) % 60);
      err_ << line << (done == total_ ? "\n" : "") << std::flush;
    } else if (done == total_ || done * 10 / total_ != (done - 1) * 10 / total_) {
      std::snprintf(line, sizeof line, "render: %lld/%lld frames, %.1f fps, ETA %.0f s\n",
                    static_cast<long long>(done), static_cast<long long>(total_), fps, eta);
      err_ << line << std::flush;
    }
  }

 private:
  std::ostream& err_;
  std::int64_t total_;
  bool enabled_;
  bool terminal_;
  std::chrono::steady_clock::time_point start_;
};

}  // namespace

int run_render(const RenderOptions& o, std::ostream& out, std::ostream& err) {
  const Fail fail{err};
  auto kind = output_kind(o);
  if (!kind) return fail(kind.error());
  std::vector<std::string> draft_notes;
  auto scene = performance::load_scene_or_music(o.scene, {}, &draft_notes);
  if (!scene) return fail(scene.error());
  for (const std::string& note : draft_notes) err << "note: " << note << "\n";
  int width = scene->output.width;
  int height = scene->output.height;
  if (!o.size.empty()) {
    auto size = parse_size_option(o.size, 16, 16, /*even=*/true);
    if (!size) return fail(size.error());
    width = size->width;
    height = size->height;
  }
  const int fps = o.fps > 0 ? o.fps : scene->output.fps;
  if (o.fps < 0 || fps > 240) return fail("--fps " + std::to_string(o.fps) + ": must be 1..240");
  const int msaa = o.msaa > 0 ? o.msaa : scene->output.msaa;
  if (msaa != 1 && msaa != 2 && msaa != 4 && msaa != 8) {
    return fail("--msaa " + std::to_string(msaa) + ": must be 1, 2, 4 or 8");
  }
  if (!o.shadows.empty() && o.shadows != "hard" && o.shadows != "soft") {
    return fail("--shadows \"" + o.shadows + "\": must be hard or soft");
  }
  if (!(o.tempo >= runtime::kMinTempo && o.tempo <= runtime::kMaxTempo)) {
    return fail("--tempo: must be in [0.1, 4]");
  }
  const bool soft_shadows = o.shadows.empty() ? scene->output.soft_shadows : o.shadows == "soft";

  int fixed_camera = -1;
  if (!o.camera.empty()) {
    fixed_camera = scene->find_camera(o.camera);
    if (fixed_camera < 0) {
      return fail("--camera \"" + o.camera + "\": " + scene->source + " has no such camera");
    }
  }

  stage::StageOptions stage_options;
  stage_options.asset_dir = o.assets;
  auto stage = performance::build_stage(*scene, stage_options);
  if (!stage) return fail(Error{scene->source + ": " + stage.error().message, stage.error().code});
  stage::Stage& st = **stage;

  const std::int64_t total = frame_count(0.0, (st.end_s() - st.start_s()) / o.tempo, fps);
  FrameRange range{0, total};
  if (!o.still.empty()) {
    char* end = nullptr;
    const double t = std::strtod(o.still.c_str(), &end);
    if (o.still.empty() || end != o.still.c_str() + o.still.size() || !std::isfinite(t)) {
      return fail("--still \"" + o.still + "\" is not a time in seconds");
    }
    range = {0, 1};
  } else if (!o.frames.empty() && !o.seconds.empty()) {
    return fail("--frames and --seconds: give one of them");
  } else if (!o.frames.empty()) {
    auto parsed = parse_frame_range(o.frames, total);
    if (!parsed) return fail(parsed.error());
    range = *parsed;
  } else if (!o.seconds.empty()) {
    auto parsed = parse_seconds_range(o.seconds, st.start_s(), fps, total, o.tempo);
    if (!parsed) return fail(parsed.error());
    range = *parsed;
  }
  if (range.end <= range.first) return fail(o.scene.string() + ": nothing to render");

  render::VulkanContextOptions context_options;
  context_options.validation = o.validate;
  context_options.device = o.device;
  auto context = render::VulkanContext::create(context_options);
  if (!context) return fail(context.error());
  auto target = render::OffscreenTarget::create(**context, static_cast<std::uint32_t>(width),
                                                static_cast<std::uint32_t>(height), 2,
                                                render::sample_count_flag(msaa));
  if (!target) return fail(target.error());
  render::ModelRendererOptions renderer_options;
  renderer_options.shadow_taps = soft_shadows ? 4 : 1;
  auto renderer = runtime::StageRenderer::create(**context, **target, st, renderer_options);
  if (!renderer) return fail(renderer.error());

  // Sound first: ffmpeg reads the WAV while the frames arrive. Without --wav the track goes
  // through a temporary file next to the video, removed at the end.
  const bool with_audio =
      o.still.empty() && (!o.wav.empty() || (*kind == OutputKind::video && o.audio));
  std::filesystem::path audio_file = o.wav;
  struct RemoveOnExit {
    std::filesystem::path path;
    ~RemoveOnExit() {
      std::error_code ignored;
      if (!path.empty()) std::filesystem::remove(path, ignored);
    }
  } temporary_audio;
  if (with_audio) {
    SceneAudioOptions audio_options;
    audio_options.sound_font = o.soundfont;
    audio_options.tempo_factor = o.tempo;
    auto sound = render_scene_audio(st, fps, range.first, range.end, audio_options);
    if (!sound) return fail(sound.error());
    if (audio_file.empty()) {
      audio_file = o.output;
      audio_file += ".tutti-audio.wav";
      temporary_audio.path = audio_file;
    }
    if (Status s = audio::write_wav(audio_file, *sound); !s) return fail(s.error());
  }

  std::unique_ptr<VideoPipe> video;
  if (*kind == OutputKind::video) {
    VideoEncoding encoding;
    encoding.lossless = o.lossless;
    encoding.comment =
        format_slice_tag({range.first, range.end, fps, o.tempo, width, height, o.lossless});
    auto opened = VideoPipe::open(o.output, static_cast<std::uint32_t>(width),
                                  static_cast<std::uint32_t>(height), fps,
                                  o.audio ? audio_file : std::filesystem::path{}, encoding);
    if (!opened) return fail(opened.error());
    video = std::move(*opened);
  } else if (*kind == OutputKind::folder) {
    std::error_code ec;
    std::filesystem::create_directories(o.output, ec);
    if (ec) return fail(o.output.string() + ": cannot create the folder (" + ec.message() + ")");
  }

  const float aspect = static_cast<float>(width) / static_cast<float>(height);
  std::vector<std::uint8_t> rgba;
  Progress progress(err, range.end - range.first, o.progress && o.still.empty());

  // Frame k is rendered while frame k - 1 is read back and written (the target's 2-slot ring).
  std::uint64_t pending_id = 0;
  std::int64_t pending_frame = -1;
  auto flush = [&]() -> Status {
    if (pending_frame < 0) return Status::success();
    if (Status s = (*target)->read_pixels(pending_id, rgba); !s) return s;
    if (o.validate && (*context)->validation_log()->size() > 0) {
      return Error{"Vulkan validation: " + (*context)->validation_log()->messages().front()};
    }
    Status written;
    if (*kind == OutputKind::video) {
      written = video->write(rgba);
    } else {
      std::filesystem::path file = o.output;
      if (*kind == OutputKind::folder) {
        char name[32];
        std::snprintf(name, sizeof name, "frame_%06lld.png", static_cast<long long>(pending_frame));
        file /= name;
      }
      written = image::write_png(file, rgba, static_cast<std::uint32_t>(width),
                                 static_cast<std::uint32_t>(height));
    }
    if (!written) return written;
    progress.frame_done(pending_frame - range.first + 1);
    pending_frame = -1;
    return Status::success();
  };
  // Frame k is posed at its time on the offline frame clock (where the rendered sound has it),
  // given as the frame's time; a still shows its own time. The frames are posed in a sampling
  // context of the render's own: the stage is only read.
  stage::StageContext posed = st.make_context();
  for (std::int64_t k = range.first; k < range.end; ++k) {
    const double t = o.still.empty()
                         ? audio_sync::offline_frame_time(st.start_s(), fps, k, o.tempo)
                         : std::strtod(o.still.c_str(), nullptr);
    st.run(posed, {t, o.still.empty() ? o.tempo / fps : 0.0});
    auto frame = (*target)->begin_frame();
    if (!frame) return fail(frame.error());
    if (Status s = (*renderer)->record(
            *frame, **target, st, posed,
            fixed_camera >= 0
                ? runtime::scene_camera(st, static_cast<std::size_t>(fixed_camera), aspect)
                : runtime::camera_at(st, t, aspect));
        !s) {
      return fail(s.error());
    }
    auto id = (*target)->end_frame();
    if (!id) return fail(id.error());
    if (Status s = flush(); !s) return fail(s.error());
    pending_id = *id;
    pending_frame = k;
  }
  if (Status s = flush(); !s) return fail(s.error());
  if (video) {
    if (Status s = video->finish(); !s) return fail(s.error());
  }
  for (const std::string& note : st.notes()) err << "note: " << note << "\n";
  out << "render: wrote " << o.output.string() << " (" << (range.end - range.first) << " frame"
      << (range.end - range.first == 1 ? "" : "s") << ", " << width << "x" << height << ", " << fps
      << " fps" << (*kind == OutputKind::video && with_audio && o.audio ? ", AAC audio" : "")
      << ")\n";
  if (!o.wav.empty()) out << "render: wrote " << o.wav.string() << " (48 kHz, 16-bit stereo)\n";
  return kExitOk;
}

void register_render_command(Commands& commands) {
  // The options, and the flags that turn one of them off (applied when the command runs).
  struct State {
    RenderOptions options;
    bool no_audio = false;
    bool no_progress = false;
  };
  auto state = std::make_shared<State>();
  Command& command = commands.add(
      "render",
      "Render a scene (content/scenes/*.json), or a MIDI / MusicXML piece as `tutti scene new` "
      "would stage it, offline on the Vulkan device: H.264 .mp4, a folder of PNG frames, or one "
      ".png with --still");
  command.option("SCENE", state->options.scene, "scene file, or a .mid / .musicxml / .mxl piece")
      .required();
  command.option("-o,--output", state->options.output, "OUT.mp4, OUT.png (--still) or FOLDER/")
      .required();
  command.option("--size", state->options.size, "WxH (default: the scene's)");
  command.option("--fps", state->options.fps, "frames per second (default: the scene's)");
  command.option("--msaa", state->options.msaa, "samples per pixel: 1, 2, 4 or 8");
  command.option("--wav", state->options.wav, "also write the rendered range's audio (WAV)");
  command.option("--soundfont", state->options.soundfont,
                 "General MIDI .sf2 (default: $TUTTI_SOUNDFONT, then Debian's)");
  command.flag("--no-audio", state->no_audio, "an .mp4 without a sound track");
  command.flag("--lossless", state->options.lossless,
               "lossless H.264: slices joined by tutti concat equal a single render");
  command.option("--tempo", state->options.tempo,
                 "practice tempo, 0.1..4 (0.5 = half speed: picture and sound)");
  command.option("--camera", state->options.camera,
                 "render every frame through this scene camera (ignore the shot list)");
  command.option("--shadows", state->options.shadows,
                 "hard (one shadow-map comparison per pixel) or soft (four)");
  command.option("--frames", state->options.frames, "A:B, frames A (inclusive) to B (exclusive)");
  command.option("--seconds", state->options.seconds, "A:B, the frames whose times are in [A, B)");
  command.option("--still", state->options.still, "one frame at this time (seconds) to a .png");
  command.option("--device", state->options.device, "Vulkan device: index or part of its name");
  command.option("--assets", state->options.assets, "folder of the generated .glb assets");
  command.flag("--validate", state->options.validate,
               "run with the Vulkan validation layer; any message is an error");
  command.flag("--no-progress", state->no_progress, "no progress output");
  command.on_run([state](std::ostream& out, std::ostream& err) {
    state->options.audio = !state->no_audio;
    state->options.progress = !state->no_progress;
    return run_render(state->options, out, err);
  });
}

}  // namespace tutti::cli
