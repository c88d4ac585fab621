// SPDX-License-Identifier: MIT
#include <tutti/cli/pose_check.hpp>

#include <cmath>
#include <cstdint>
#include <cstdio>
#include <string>

#include <tutti/stage/family_plugin.hpp>
#include <tutti/stage/finger_joint_limits.hpp>
#include <tutti/stage/pose_checker.hpp>

namespace tutti::cli {

Result<PoseReport> check_pose(const stage::Stage& stage, const PoseCheckOptions& options) {
  if (options.fps < 1 || options.fps > 240) return Error{"fps must be 1..240"};
  if (!(options.to_s > options.from_s)) return Error{"nothing to check: the range is empty"};
  auto limits = stage::load_finger_joint_limits(options.content_dir);
  if (!limits) return limits.error();
  PoseReport report;
  // The frames are posed in a sampling context of its own: the stage is only read.
  stage::StageContext context = stage.make_context();
  stage::PoseChecker checker(context.world(), report, *limits);
  const auto families = stage.families();
  const auto family_of = [&](ecs::Entity performer) -> const stage::FamilyPlugin* {
    const auto* seat = context.world().try_get<stage::Seat>(performer);
    if (seat == nullptr) return nullptr;
    for (const stage::FamilyPlugin* family : families) {
      if (family->name() == seat->family) return family;
    }
    return nullptr;
  };
  const double dt = 1.0 / options.fps;
  const auto frames = static_cast<std::int64_t>(std::ceil((options.to_s - options.from_s) * options.fps));
  for (std::int64_t k = 0; k < frames; ++k) {
    const double t = options.from_s + static_cast<double>(k) * dt;
    stage.run(context, {t, dt});
    ++report.frames;
    checker.at_time(t, dt);
    for (ecs::Entity performer : stage.performers()) {
      if (const stage::FamilyPlugin* family = family_of(performer)) {
        family->check_pose(checker, performer);
      }
    }
  }
  for (const stage::FamilyPlugin* family : families) family->finish_pose_check(checker);
  return report;
}

std::string format_pose_report(const PoseReport& report) {
  std::string out;
  char line[512];
  std::snprintf(line, sizeof line, "%zu frames\n%-80s %7s %7s %7s %7s %7s %10s  %s\n",
                report.frames, "measure", "samples", "min", "median", "p95", "max", "limit",
                "worst at");
  out += line;
  for (const PoseMeasure& m : report.measures) {
    char limit[32] = "";
    if (m.limit >= 0.0) {
      std::snprintf(limit, sizeof limit, "%s%g %s", m.by_p95 ? "p95<=" : m.two_sided ? "|x|<=" : "<=",
                    m.limit, m.within_limit() ? "ok" : "OVER");
    }
    char at[96] = "";
    if (m.samples.size() > 1 || !m.worst_of.empty()) {
      std::snprintf(at, sizeof at, "%.2f s%s%s%s", m.worst_at_s, m.worst_of.empty() ? "" : " (",
                    m.worst_of.c_str(), m.worst_of.empty() ? "" : ")");
    }
    std::snprintf(line, sizeof line, "%-80s %7zu %7.1f %7.1f %7.1f %7.1f %10s  %s\n",
                  (m.name + " (" + m.unit + ")").c_str(), m.samples.size(), m.percentile(0.0),
                  m.percentile(0.5), m.percentile(0.95), m.worst(), limit, at);
    out += line;
  }
  return out;
}

}  // namespace tutti::cli
