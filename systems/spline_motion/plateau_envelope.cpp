// SPDX-License-Identifier: MIT
#include <tutti/spline_motion/plateau_envelope.hpp>

#include <algorithm>
#include <cstddef>
#include <map>

namespace tutti::spline_motion {
namespace {

// 10u^3 - 15u^4 + 6u^5 on u clamped to [0, 1] (as finger_motion's finger_chain.hpp writes it).
double min_jerk(double u) noexcept {
  u = std::clamp(u, 0.0, 1.0);
  return u * u * u * (10.0 + u * (-15.0 + 6.0 * u));
}

struct Step {
  double t_s;
  double value;
};

// The upper envelope of the needs as steps: a sweep over their starts and ends with the active
// values counted in a multiset (a map of value -> count).
std::vector<Step> envelope(std::vector<EnvelopeNeed>& needs) {
  struct Edge {
    double t_s;
    double value;
    bool starts;
  };
  std::vector<Edge> edges;
  edges.reserve(2 * needs.size());
  for (const EnvelopeNeed& n : needs) {
    if (!(n.value > 0.0) || !(n.to_s >= n.from_s)) continue;
    edges.push_back({n.from_s, n.value, true});
    edges.push_back({n.to_s, n.value, false});
  }
  // At one time, ends before starts would open a gap: starts first.
  std::sort(edges.begin(), edges.end(), [](const Edge& a, const Edge& b) {
    if (a.t_s != b.t_s) return a.t_s < b.t_s;
    if (a.starts != b.starts) return a.starts;
    return a.value < b.value;
  });
  std::map<double, int> active;
  std::vector<Step> steps;
  for (std::size_t i = 0; i < edges.size();) {
    const double t = edges[i].t_s;
    for (; i < edges.size() && edges[i].t_s == t; ++i) {
      if (edges[i].starts) {
        ++active[edges[i].value];
      } else if (auto it = active.find(edges[i].value); it != active.end() && --it->second == 0) {
        active.erase(it);
      }
    }
    const double value = active.empty() ? 0.0 : active.rbegin()->first;
    const double before = steps.empty() ? 0.0 : steps.back().value;
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
      const double left = steps[i - 1].value;
      const double right = steps[i + 1].value;
      if (steps[i].value < left && steps[i].value < right &&
          steps[i + 1].t_s - steps[i].t_s < bridge_s) {
        steps[i].value = std::min(left, right);
        changed = true;
      }
    }
    // Merge neighbours that became equal.
    std::vector<Step> merged;
    merged.reserve(steps.size());
    for (const Step& s : steps) {
      const double before = merged.empty() ? 0.0 : merged.back().value;
      if (s.value != before) merged.push_back(s);
    }
    changed = changed || merged.size() != steps.size();
    steps = std::move(merged);
  }
}

}  // namespace

PlateauEnvelope plan_plateau_envelope(std::vector<EnvelopeNeed> needs, double ramp_s,
                                      double bridge_s) {
  std::vector<Step> steps = envelope(needs);
  bridge_dips(steps, bridge_s);
  PlateauEnvelope path;
  path.ramp_s = ramp_s;
  for (std::size_t i = 0; i < steps.size(); ++i) {
    if (!(steps[i].value > 0.0)) continue;
    // The envelope always comes back to 0 (every need ends), so a step > 0 has a next.
    const double end = i + 1 < steps.size() ? steps[i + 1].t_s : steps[i].t_s;
    path.starts_s.push_back(steps[i].t_s);
    path.ends_s.push_back(end);
    path.values.push_back(steps[i].value);
  }
  return path;
}

double evaluate_plateau_envelope(const PlateauEnvelope& path, double t_s) noexcept {
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
    in = std::max(in, weight * path.values[index]);
  }
  return in;
}

}  // namespace tutti::spline_motion
