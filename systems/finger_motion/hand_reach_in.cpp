#include <tutti/finger_motion/hand_reach_in.hpp>

#include <algorithm>
#include <cstddef>
#include <map>

#include <tutti/finger_motion/finger_chain.hpp>

namespace tutti::finger_motion {
namespace {

struct Step {
  double t_s;
  double value_mm;
};

// The upper envelope of the needs as steps: a sweep over their starts and ends with the active
// values counted in a multiset (a map of value -> count).
std::vector<Step> envelope(std::vector<ReachInNeed>& needs) {
  struct Edge {
    double t_s;
    double value_mm;
    bool starts;
  };
  std::vector<Edge> edges;
  edges.reserve(2 * needs.size());
  for (const ReachInNeed& n : needs) {
    if (!(n.in_mm > 0.0) || !(n.to_s >= n.from_s)) continue;
    edges.push_back({n.from_s, n.in_mm, true});
    edges.push_back({n.to_s, n.in_mm, false});
  }
  // At one time, ends before starts would open a gap: starts first.
  std::sort(edges.begin(), edges.end(), [](const Edge& a, const Edge& b) {
    if (a.t_s != b.t_s) return a.t_s < b.t_s;
    if (a.starts != b.starts) return a.starts;
    return a.value_mm < b.value_mm;
  });
  std::map<double, int> active;
  std::vector<Step> steps;
  for (std::size_t i = 0; i < edges.size();) {
    const double t = edges[i].t_s;
    for (; i < edges.size() && edges[i].t_s == t; ++i) {
      if (edges[i].starts) {
        ++active[edges[i].value_mm];
      } else if (auto it = active.find(edges[i].value_mm); it != active.end() && --it->second == 0) {
        active.erase(it);
      }
    }
    const double value = active.empty() ? 0.0 : active.rbegin()->first;
    const double before = steps.empty() ? 0.0 : steps.back().value_mm;
    if (value != before) steps.push_back({t, value});
  }
  return steps;
}

// Raises a short dip between two higher steps to the lower of them, until none is left.
void bridge_dips(std::vector<Step>& steps, double bridge_s) {
  bool changed = true;
  while (changed) {
    changed = false;
    for (std::size_t i = 1; i + 1 < steps.size(); ++i) {
      const double left = steps[i - 1].value_mm;
      const double right = steps[i + 1].value_mm;
      if (steps[i].value_mm < left && steps[i].value_mm < right &&
          steps[i + 1].t_s - steps[i].t_s < bridge_s) {
        steps[i].value_mm = std::min(left, right);
        changed = true;
      }
    }
    // Merge neighbours that became equal.
    std::vector<Step> merged;
    merged.reserve(steps.size());
    for (const Step& s : steps) {
      const double before = merged.empty() ? 0.0 : merged.back().value_mm;
      if (s.value_mm != before) merged.push_back(s);
    }
    changed = changed || merged.size() != steps.size();
    steps = std::move(merged);
  }
}

}  // namespace

HandReachIn plan_reach_in(std::vector<ReachInNeed> needs, double ramp_s, double bridge_s) {
  std::vector<Step> steps = envelope(needs);
  bridge_dips(steps, bridge_s);
  HandReachIn path;
  path.times_s.reserve(steps.size());
  path.values_mm.reserve(steps.size());
  path.ramp_s.reserve(steps.size());
  for (std::size_t i = 0; i < steps.size(); ++i) {
    const double before = i == 0 ? 0.0 : steps[i - 1].value_mm;
    const bool rises = steps[i].value_mm > before;
    // A rise eases during the step before it, a fall during the step after: half of it at most,
    // so two eases never overlap.
    double room = ramp_s;
    if (rises && i > 0) room = std::min(room, 0.5 * (steps[i].t_s - steps[i - 1].t_s));
    if (!rises && i + 1 < steps.size()) room = std::min(room, 0.5 * (steps[i + 1].t_s - steps[i].t_s));
    path.times_s.push_back(steps[i].t_s);
    path.values_mm.push_back(steps[i].value_mm);
    path.ramp_s.push_back(room);
  }
  return path;
}

double evaluate_reach_in(const HandReachIn& path, double t_s) noexcept {
  const std::vector<double>& times = path.times_s;
  if (times.empty()) return 0.0;
  // The last boundary at or before t (-1: before the first).
  const auto next = static_cast<std::size_t>(
      std::upper_bound(times.begin(), times.end(), t_s) - times.begin());
  const auto value = [&](std::size_t after) { return path.values_mm[after]; };
  const double here = next == 0 ? 0.0 : value(next - 1);
  if (next > 0) {
    const std::size_t k = next - 1;
    const double before = k == 0 ? 0.0 : value(k - 1);
    if (here < before && t_s < times[k] + path.ramp_s[k]) {  // falling after boundary k
      return blend(before, here, min_jerk((t_s - times[k]) / path.ramp_s[k]));
    }
  }
  if (next < times.size()) {
    const double after = value(next);
    const double start = times[next] - path.ramp_s[next];
    if (after > here && t_s > start) {  // rising before boundary next
      return blend(here, after, min_jerk((t_s - start) / path.ramp_s[next]));
    }
  }
  return here;
}

}  // namespace tutti::finger_motion
