// SPDX-License-Identifier: MIT
#include <tutti/cli/export_command.hpp>

#include <cmath>
#include <memory>
#include <nlohmann/json.hpp>
#include <ostream>
#include <string>

#include <tutti/core/exit_codes.hpp>
#include <tutti/cli/frame_range.hpp>
#include <tutti/core/file_io.hpp>
#include <tutti/export/scene_export.hpp>
#include <tutti/cli/stage_scene.hpp>
#include <tutti/stage/stage.hpp>

namespace tutti::cli {

int run_export(const ExportOptions& o, std::ostream& out, std::ostream& err) {
  const Fail fail{err};
  if (o.output.extension() != ".glb") {
    return fail(o.output.string() + ": the output is a .glb file (binary glTF 2.0)");
  }
  if (o.fps != 0 && (o.fps < 1 || o.fps > 240)) return fail("--fps: must be in [1, 240]");
  if (!o.frames.empty() && !o.seconds.empty()) return fail("--frames and --seconds: give one");

  auto staged = stage_scene_file(o.scene, o.assets);
  if (!staged) return fail(staged.error());
  stage::Stage& stage = **staged;
  const scene::Scene* scene = &stage.scene();

  const int fps = o.fps != 0 ? o.fps : scene->output.fps;
  const std::int64_t total = frame_count(stage.start_s(), stage.end_s(), fps);
  FrameRange range{0, total};
  if (!o.frames.empty()) {
    auto parsed = parse_frame_range(o.frames, total);
    if (!parsed) return fail(parsed.error());
    range = *parsed;
  } else if (!o.seconds.empty()) {
    auto parsed = parse_seconds_range(o.seconds, stage.start_s(), fps, total);
    if (!parsed) return fail(parsed.error());
    range = *parsed;
  }
  if (range.end <= range.first) return fail(o.scene.string() + ": nothing to export");

  const gltf_export::KeyTolerances tolerances;
  auto exported = gltf_export::export_performance(
      stage, {fps, range.first, range.end - range.first}, tolerances);
  if (!exported) return fail(exported.error());
  const gltf_export::ExportSummary& summary = *exported;
  const Status written =
      write_file_atomically(o.output, std::string(summary.glb.begin(), summary.glb.end()));
  if (!written) return fail(written.error());

  if (o.json_summary) {
    nlohmann::json clips = nlohmann::json::array();
    for (const auto& clip : summary.clips) {
      clips.push_back({{"name", clip.name}, {"channels", clip.channels}, {"keys", clip.keys}});
    }
    out << nlohmann::json{{"file", o.output.string()},
                          {"bytes", summary.glb.size()},
                          {"fps", fps},
                          {"first_frame", range.first},
                          {"frames", range.end - range.first},
                          {"duration_s", summary.duration_s},
                          {"nodes", summary.nodes},
                          {"meshes", summary.meshes},
                          {"skins", summary.skins},
                          {"samples", summary.samples},
                          {"keys", summary.keys},
                          {"clips", clips}}
               .dump()
        << "\n";
    return kExitOk;
  }
  out << o.output.string() << ": " << summary.glb.size() << " bytes; " << summary.nodes
      << " nodes, " << summary.meshes << " meshes, " << summary.skins << " skins; frames "
      << range.first << ".." << range.end - 1 << " at " << fps << " fps (" << summary.duration_s
      << " s)\n";
  const double kept = summary.samples > 0 ? 100.0 * static_cast<double>(summary.keys) /
                                                static_cast<double>(summary.samples)
                                          : 0.0;
  out << "keys: " << summary.keys << " of " << summary.samples << " samples kept ("
      << std::round(kept * 10.0) / 10.0 << " %); tolerance " << tolerances.translation_m * 1000.0f
      << " mm, " << glm::degrees(tolerances.rotation_rad) << " deg, scale " << tolerances.scale
      << ", weight " << tolerances.weight << "\n";
  for (const auto& clip : summary.clips) {
    out << "  clip \"" << clip.name << "\": " << clip.channels << " channels, " << clip.keys
        << " keys\n";
  }
  return kExitOk;
}

void register_export_command(Commands& commands) {
  auto options = std::make_shared<ExportOptions>();
  Command& command = commands.add(
      "export",
      "Write the scene as binary glTF 2.0: characters, hands, piano, instruments and props with "
      "the performance baked as animation (one clip per performer plus the whole scene)");
  command.option("SCENE", options->scene, "scene file (.json)").required();
  command.option("-o,--output", options->output, "performance.glb").required();
  command.option("--fps", options->fps, "keyframe rate (default: the scene's)");
  command.option("--seconds", options->seconds, "A:B: the frames whose times are in [A, B)");
  command.option("--frames", options->frames, "A:B: frames A (inclusive) to B (exclusive)");
  command.option("--assets", options->assets, "folder of the generated .glb assets");
  command.flag("--json", options->json_summary, "print the summary as JSON");
  command.on_run(
      [options](std::ostream& out, std::ostream& err) { return run_export(*options, out, err); });
}

}  // namespace tutti::cli
