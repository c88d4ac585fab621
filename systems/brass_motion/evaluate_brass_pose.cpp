// SPDX-License-Identifier: MIT
#include <tutti/brass_motion/evaluate_brass_pose.hpp>

#include <algorithm>

namespace tutti::brass_motion {
namespace {

// Last element whose start (by `key`) is <= t, or nullptr.
template <typename T, typename Key>
const T* last_started(const std::vector<T>& items, double t, Key key) {
  auto it = std::upper_bound(items.begin(), items.end(), t,
                             [&](double value, const T& item) { return value < key(item); });
  return it == items.begin() ? nullptr : &*(it - 1);
}

double ease(double t, double start, double end) {
  if (t <= start) return 0.0;
  if (t >= end) return 1.0;
  return min_jerk((t - start) / (end - start));
}

float valve_press(const std::vector<ValveStroke>& strokes, double t) {
  const ValveStroke* s = last_started(strokes, t, [](const ValveStroke& v) { return v.press_s; });
  if (s == nullptr) return 0.0f;
  if (t < s->down_s) return static_cast<float>(ease(t, s->press_s, s->down_s));
  if (t < s->release_s) return 1.0f;
  return static_cast<float>(1.0 - ease(t, s->release_s, s->up_s));
}

}  // namespace

double min_jerk(double u, double* slope) {
  u = std::clamp(u, 0.0, 1.0);
  const double u2 = u * u;
  if (slope != nullptr) *slope = 30.0 * u2 * (1.0 - u) * (1.0 - u);
  return u2 * u * (10.0 - 15.0 * u + 6.0 * u2);
}

BrassPose evaluate_brass_pose(const BrassMotionPlan& plan, double t) {
  BrassPose pose;
  for (int v = 0; v < plan.valve_count; ++v) {
    pose.valve_press[static_cast<std::size_t>(v)] =
        valve_press(plan.valves[static_cast<std::size_t>(v)], t);
  }
  if (plan.has_slide) {
    pose.slide_mm = plan.slide_start_mm;
    pose.slide_position = plan.slide_start_position;
    if (const SlideMove* m =
            last_started(plan.slide, t, [](const SlideMove& s) { return s.start_s; })) {
      const double length = m->end_s - m->start_s;
      double slope = 0.0;
      const double u =
          t >= m->end_s || length <= 0.0 ? 1.0 : min_jerk((t - m->start_s) / length, &slope);
      pose.slide_mm = m->from_mm + (m->to_mm - m->from_mm) * u;
      pose.slide_position = m->from_position + (m->to_position - m->from_position) * u;
      if (t < m->end_s && length > 0.0) {
        pose.slide_speed_mm_per_s = (m->to_mm - m->from_mm) * slope / length;
      }
    }
  }
  pose.tension = plan.rest_tension;
  if (const TensionRamp* r =
          last_started(plan.tension, t, [](const TensionRamp& x) { return x.start_s; })) {
    pose.tension = r->from + (r->to - r->from) * ease(t, r->start_s, r->end_s);
  }
  const double from = plan.corner_pull_from;
  pose.corner_pull = pose.tension <= from ? 0.0 : min_jerk((pose.tension - from) / (1.0 - from));
  if (const SoundingSpan* s =
          last_started(plan.sounding, t, [](const SoundingSpan& x) { return x.onset_s; })) {
    pose.buzzing = t < s->offset_s;
  }
  return pose;
}

}  // namespace tutti::brass_motion
