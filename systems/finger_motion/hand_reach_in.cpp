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
  path.ramp_s = ramp_s;
  for (std::size_t i = 0; i < steps.size(); ++i) {
    if (!(steps[i].value_mm > 0.0)) continue;
    // The envelope always comes back to 0 (every need ends), so a step > 0 has a next.
    const double end = i + 1 < steps.size() ? steps[i + 1].t_s : steps[i].t_s;
    path.starts_s.push_back(steps[i].t_s);
    path.ends_s.push_back(end);
    path.values_mm.push_back(steps[i].value_mm);
  }
  return path;
}

double evaluate_reach_in(const HandReachIn& path, double t_s) noexcept {
  const double ramp = path.ramp_s;
  // Plateaus beginning after t + ramp cannot reach t yet; going back from there, the first
  // ending before t - ramp and all earlier ones have eased out (they are in time order).
  auto index = static_cast<std::size_t>(
      std::upper_bound(path.starts_s.begin(), path.starts_s.end(), t_s + ramp) -
      path.starts_s.begin());
  double in = 0.0;
  while (index > 0) {
    --index;
    const double start = path.starts_s[index];
    const double end = path.ends_s[index];
    if (end < t_s - ramp) break;
    double weight = 1.0;
    if (t_s < start) {
      weight = min_jerk((t_s - (start - ramp)) / ramp);
    } else if (t_s > end) {
      weight = 1.0 - min_jerk((t_s - end) / ramp);
    }
    in = std::max(in, weight * path.values_mm[index]);
  }
  return in;
}

}  // namespace tutti::finger_motion
