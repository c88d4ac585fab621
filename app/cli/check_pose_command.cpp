// SPDX-License-Identifier: MIT
#include <tutti/cli/check_pose_command.hpp>

#include <algorithm>
#include <cstdio>
#include <memory>
#include <nlohmann/json.hpp>
#include <ostream>

#include <tutti/core/exit_codes.hpp>
#include <tutti/cli/pose_check.hpp>
#include <tutti/cli/stage_scene.hpp>

namespace tutti::cli {

int run_check_pose(const CheckPoseOptions& o, std::ostream& out, std::ostream& err) {
  const Fail fail{err};
  if (o.fps < 1 || o.fps > 240) return fail("--fps " + std::to_string(o.fps) + ": must be 1..240");
  auto staged = stage_scene_file(o.scene, o.assets);
  if (!staged) return fail(staged.error());
  stage::Stage& stage = **staged;
  const scene::Scene* scene = &stage.scene();
  PoseCheckOptions options;
  options.fps = o.fps;
  options.from_s = stage.start_s();
  options.to_s = std::min(stage.end_s(), stage.start_s() + 12.0);
  if (o.seconds == "all") {
    options.to_s = stage.end_s();
  } else if (!o.seconds.empty()) {
    double from = 0.0;
    double to = 0.0;
    char extra = 0;
    if (std::sscanf(o.seconds.c_str(), "%lf:%lf%c", &from, &to, &extra) != 2 || !(to > from)) {
      return fail("--seconds \"" + o.seconds + "\": expected A:B with A < B, or all");
    }
    options.from_s = from;
    // Past the music's end nothing moves: the range stops there.
    options.to_s = std::min(to, stage.end_s());
    if (!(options.to_s > options.from_s)) {
      return fail("--seconds \"" + o.seconds + "\": the music ends at " +
                  std::to_string(stage.end_s()) + " s");
    }
  }
  auto report = check_pose(stage, options);
  if (!report) return fail(Error{scene->source + ": " + report.error().message, report.error().code});
  bool over = false;
  for (const PoseMeasure& m : report->measures) over = over || !m.within_limit();
  if (o.json) {
    nlohmann::json doc;
    doc["scene"] = scene->source;
    doc["from_s"] = options.from_s;
    doc["to_s"] = options.to_s;
    doc["fps"] = options.fps;
    doc["frames"] = report->frames;
    doc["measures"] = nlohmann::json::array();
    for (const PoseMeasure& m : report->measures) {
      nlohmann::json j{{"name", m.name},       {"unit", m.unit},
                       {"samples", m.samples.size()}, {"min", m.percentile(0.0)}, {"median", m.percentile(0.5)},
                       {"p95", m.percentile(0.95)},   {"max", m.worst()},
                       {"within_limit", m.within_limit()}, {"worst_at_s", m.worst_at_s}};
      if (!m.worst_of.empty()) j["worst_of"] = m.worst_of;
      if (m.limit >= 0.0) {
        j["limit"] = {{"value", m.limit}, {"of", m.by_p95 ? "p95" : m.two_sided ? "abs" : "max"}};
      }
      doc["measures"].push_back(j);
    }
    out << doc.dump(2) << "\n";
  } else {
    char heading[160];
    std::snprintf(heading, sizeof heading, "check-pose: %s, %.2f .. %.2f s at %d fps, ",
                  scene->source.c_str(), options.from_s, options.to_s, options.fps);
    out << heading << format_pose_report(*report);
  }
  return o.check && over ? kExitPoseLimitOver : kExitOk;
}

void register_check_pose_command(Commands& commands) {
  auto options = std::make_shared<CheckPoseOptions>();
  Command& command = commands.add(
      "check-pose",
      "Measure the posed performers frame by frame: pressing fingertips to their buttons and "
      "keys, hands to the instruments, hands inside heads, piano keys left half down");
  command.option("SCENE", options->scene, "scene file").required();
  command.option("--seconds", options->seconds,
                 "A:B, seconds of the music, or all (default: the first 12 s shown)");
  command.option("--fps", options->fps, "frames per second sampled (default 30)");
  command.option("--assets", options->assets, "folder of the generated .glb assets");
  command.flag("--json", options->json, "print JSON instead of text");
  command.flag("--check", options->check, "exit 4 when a figure is over its limit");
  command.on_run([options](std::ostream& out, std::ostream& err) {
    return run_check_pose(*options, out, err);
  });
}

}  // namespace tutti::cli
