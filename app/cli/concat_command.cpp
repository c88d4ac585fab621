// SPDX-License-Identifier: MIT
#include <tutti/cli/concat_command.hpp>

#include <unistd.h>

#include <algorithm>
#include <fstream>
#include <memory>
#include <ostream>
#include <system_error>

#include <tutti/core/exit_codes.hpp>
#include <tutti/cli/run_tool.hpp>
#include <tutti/cli/scene_audio.hpp>
#include <tutti/cli/slice_tag.hpp>
#include <tutti/audio/wav_file.hpp>
#include <tutti/scene/load_scene.hpp>
#include <tutti/performance/families.hpp>
#include <tutti/stage/stage.hpp>

namespace tutti::cli {
namespace {

namespace fs = std::filesystem;

struct Slice {
  fs::path file;
  SliceTag tag;
};

Result<Slice> read_slice(const fs::path& file) {
  std::error_code ec;
  if (!fs::is_regular_file(file, ec)) return Error{file.string() + ": no such file"};
  auto printed = run_tool({"ffprobe", "-v", "error", "-show_entries", "format_tags=comment", "-of",
                           "default=noprint_wrappers=1:nokey=1", file.string()},
                          file.string());
  if (!printed) return printed.error();
  const std::optional<SliceTag> tag = parse_slice_tag(*printed);
  if (!tag) {
    return Error{file.string() +
                 ": not a slice made by tutti render (its comment tag has no tutti-slice frames)"};
  }
  return Slice{file, *tag};
}

// The concat demuxer's list: one quoted absolute path per line ('\'' for a quote).
std::string concat_list(const std::vector<Slice>& slices) {
  std::string list;
  for (const Slice& slice : slices) {
    std::string quoted;
    for (char c : fs::absolute(slice.file).string()) {
      if (c == '\'') {
        quoted += "'\\''";
      } else {
        quoted += c;
      }
    }
    list += "file '" + quoted + "'\n";
  }
  return list;
}

struct RemoveOnExit {
  std::vector<fs::path> paths;
  ~RemoveOnExit() {
    std::error_code ignored;
    for (const fs::path& p : paths) fs::remove(p, ignored);
  }
};

}  // namespace

int run_concat(const ConcatOptions& o, std::ostream& out, std::ostream& err) {
  const Fail fail{err};
  if (o.output.extension() != ".mp4") {
    return fail(o.output.string() + ": the output is an .mp4 file");
  }
  if (o.slices.empty()) return fail("concat: no slices given");
  std::vector<Slice> slices;
  for (const fs::path& file : o.slices) {
    std::error_code ec;
    if (fs::exists(o.output, ec) && fs::equivalent(file, o.output, ec)) {
      return fail(o.output.string() + ": is also one of the slices");
    }
    auto slice = read_slice(file);
    if (!slice) return fail(slice.error());
    slices.push_back(std::move(*slice));
  }
  std::stable_sort(slices.begin(), slices.end(),
                   [](const Slice& a, const Slice& b) { return a.tag.first < b.tag.first; });
  const SliceTag& head = slices.front().tag;
  for (std::size_t i = 1; i < slices.size(); ++i) {
    const Slice& prev = slices[i - 1];
    const Slice& s = slices[i];
    if (s.tag.fps != head.fps || s.tag.width != head.width || s.tag.height != head.height ||
        s.tag.tempo != head.tempo || s.tag.lossless != head.lossless) {
      return fail(s.file.string() + ": rendered with other settings than " +
                  slices.front().file.string() + " (" + format_slice_tag(s.tag) + " vs " +
                  format_slice_tag(head) + ")");
    }
    if (s.tag.first != prev.tag.end) {
      return fail(s.file.string() + ": starts at frame " + std::to_string(s.tag.first) + " but " +
                  prev.file.string() + " ends at frame " + std::to_string(prev.tag.end) +
                  (s.tag.first > prev.tag.end ? " (frames missing)" : " (frames overlap)"));
    }
  }
  const SliceTag whole{head.first, slices.back().tag.end, head.fps,     head.tempo,
                       head.width, head.height,           head.lossless};

  RemoveOnExit temporary;
  const fs::path partial =
      o.output.parent_path() / ("." + o.output.filename().string() + ".tutti-concat");
  const fs::path list_file =
      o.output.parent_path() /
      ("." + o.output.filename().string() + ".tutti-concat-" + std::to_string(getpid()) + ".txt");
  temporary.paths.push_back(partial);
  temporary.paths.push_back(list_file);
  {
    std::ofstream list(list_file);
    list << concat_list(slices);
    if (!list) return fail(list_file.string() + ": cannot write the slice list");
  }
  fs::path wav;
  if (o.audio) {
    auto scene = scene::load_scene(o.scene, performance::scene_load_options());
    if (!scene) return fail(scene.error());
    stage::StageOptions stage_options;
    stage_options.asset_dir = o.assets;
    auto stage = performance::build_stage(*scene, stage_options);
    if (!stage) return fail(Error{scene->source + ": " + stage.error().message, stage.error().code});
    SceneAudioOptions audio_options;
    audio_options.sound_font = o.soundfont;
    audio_options.tempo_factor = whole.tempo;
    auto sound = render_scene_audio(**stage, whole.fps, whole.first, whole.end, audio_options);
    if (!sound) return fail(sound.error());
    wav = o.output.parent_path() / ("." + o.output.filename().string() + ".tutti-audio.wav");
    temporary.paths.push_back(wav);
    if (Status s = audio::write_wav(wav, *sound); !s) return fail(s.error());
  }
  std::vector<std::string> args = {"ffmpeg", "-nostdin", "-y", "-loglevel", "error",           "-f",
                                   "concat", "-safe",    "0",  "-i",        list_file.string()};
  if (!wav.empty()) {
    for (const std::string& a :
         {std::string("-i"), wav.string(), std::string("-map"), std::string("0:v:0"),
          std::string("-map"), std::string("1:a:0"), std::string("-c:a"), std::string("aac"),
          std::string("-b:a"), std::string("192k")}) {
      args.push_back(a);
    }
  } else {
    args.insert(args.end(), {"-map", "0:v:0", "-an"});
  }
  args.insert(args.end(), {"-c:v", "copy", "-movflags", "+faststart", "-metadata",
                           "comment=" + format_slice_tag(whole), "-f", "mp4", partial.string()});
  if (auto ran = run_tool(args, o.output.string()); !ran) return fail(ran.error());
  std::error_code ec;
  fs::rename(partial, o.output, ec);
  if (ec) return fail(o.output.string() + ": cannot replace it (" + ec.message() + ")");
  out << "concat: wrote " << o.output.string() << " (" << slices.size() << " slices, frames "
      << whole.first << ":" << whole.end << ", " << whole.width << "x" << whole.height << ", "
      << whole.fps << " fps" << (wav.empty() ? "" : ", AAC audio rendered once") << ")\n";
  return kExitOk;
}

void register_concat_command(Commands& commands) {
  // The options, and the flags that turn one of them off (applied when the command runs).
  struct State {
    ConcatOptions options;
    bool no_audio = false;
  };
  auto state = std::make_shared<State>();
  Command& command = commands.add(
      "concat",
      "Join slices of one render (tutti render SCENE --frames A:B --no-audio -o slice.mp4) into "
      "one video: frames copied exactly, the sound rendered once for the whole range");
  command.option("SCENE", state->options.scene, "the scene the slices were rendered from")
      .required();
  command.option("SLICES", state->options.slices, "slice .mp4 files, any order").required();
  command.option("-o,--output", state->options.output, "OUT.mp4").required();
  command.option("--soundfont", state->options.soundfont, "General MIDI .sf2");
  command.option("--assets", state->options.assets, "folder of the generated .glb assets");
  command.flag("--no-audio", state->no_audio, "no sound track");
  command.on_run([state](std::ostream& out, std::ostream& err) {
    state->options.audio = !state->no_audio;
    return run_concat(state->options, out, err);
  });
}

}  // namespace tutti::cli
