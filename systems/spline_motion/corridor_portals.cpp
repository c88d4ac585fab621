// SPDX-License-Identifier: MIT
#include <tutti/spline_motion/corridor_portals.hpp>

#include <algorithm>
#include <cmath>
#include <sstream>
#include <string>

namespace tutti::spline_motion {
namespace {

Error corridor_error(std::size_t index, const std::string& what) {
  std::ostringstream out;
  out << "hand corridor " << index << ": " << what;
  return Error{out.str()};
}

std::string num(double v) {
  std::ostringstream out;
  out.precision(15);
  out << v;
  return out.str();
}

}  // namespace

Status validate_corridors(std::span<const piano_model::HandCorridor> corridors) {
  for (std::size_t i = 0; i < corridors.size(); ++i) {
    const piano_model::HandCorridor& c = corridors[i];
    if (!std::isfinite(c.start_s) || !std::isfinite(c.end_s) || !std::isfinite(c.lo_mm) ||
        !std::isfinite(c.hi_mm)) {
      return corridor_error(i, "non-finite value (start_s " + num(c.start_s) + ", end_s " +
                                   num(c.end_s) + ", lo_mm " + num(c.lo_mm) + ", hi_mm " +
                                   num(c.hi_mm) + ")");
    }
    if (c.start_s > c.end_s) {
      return corridor_error(i, "start_s " + num(c.start_s) + " > end_s " + num(c.end_s));
    }
    if (c.lo_mm > c.hi_mm) {
      return corridor_error(i, "lo_mm " + num(c.lo_mm) + " > hi_mm " + num(c.hi_mm));
    }
    if (i > 0 && corridors[i - 1].end_s > c.start_s) {
      return corridor_error(i, "start_s " + num(c.start_s) + " is before the end of corridor " +
                                   std::to_string(i - 1) + " (" + num(corridors[i - 1].end_s) +
                                   "): corridors must be sorted and must not overlap in time");
    }
  }
  return Status::success();
}

Result<std::vector<Portal>> corridor_portals(std::span<const piano_model::HandCorridor> corridors) {
  if (Status status = validate_corridors(corridors); !status) return status.error();
  std::vector<Portal> portals;
  portals.reserve(2 * corridors.size());
  const auto add = [&](double t, const piano_model::HandCorridor& c, std::size_t index) -> Status {
    if (!portals.empty() && portals.back().t_s == t) {
      Portal& p = portals.back();
      const double lo = std::max(p.lo_mm, c.lo_mm);
      const double hi = std::min(p.hi_mm, c.hi_mm);
      if (lo > hi) {
        return Error{"hand corridors " + std::to_string(p.corridor) + " and " +
                     std::to_string(index) + " meet at t=" + num(t) + " s but their ranges [" +
                     num(p.lo_mm) + ", " + num(p.hi_mm) + "] and [" + num(c.lo_mm) + ", " +
                     num(c.hi_mm) +
                     "] mm do not overlap: the hand would have to jump (leave a gap in time)"};
      }
      p.lo_mm = lo;
      p.hi_mm = hi;
      return Status::success();
    }
    portals.push_back(Portal{t, c.lo_mm, c.hi_mm, index});
    return Status::success();
  };
  for (std::size_t i = 0; i < corridors.size(); ++i) {
    if (Status s = add(corridors[i].start_s, corridors[i], i); !s) return s.error();
    if (Status s = add(corridors[i].end_s, corridors[i], i); !s) return s.error();
  }
  return portals;
}

}  // namespace tutti::spline_motion
