// SPDX-License-Identifier: MIT
#include <tutti/piano_performance/corridor_repair.hpp>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <utility>

namespace tutti::piano_performance {
namespace {

struct Item {
  piano_model::HandCorridor c;
  std::size_t origin = 0;
};

bool finite(const piano_model::HandCorridor& c) {
  return std::isfinite(c.start_s) && std::isfinite(c.end_s) && std::isfinite(c.lo_mm) &&
         std::isfinite(c.hi_mm);
}

bool disjoint(const piano_model::HandCorridor& a, const piano_model::HandCorridor& b) {
  return a.hi_mm < b.lo_mm || b.hi_mm < a.lo_mm;
}

template <typename... Args>
std::string line(const char* format, Args... args) {
  char buffer[160];
  std::snprintf(buffer, sizeof buffer, format, args...);
  return buffer;
}

// Kind 2: drop non-finite, swap reversed pairs, sort, cut overlaps. Returns the items left.
std::vector<Item> sanitize(std::span<const piano_model::HandCorridor> corridors,
                           CorridorRepair& r) {
  std::vector<Item> items;
  items.reserve(corridors.size());
  for (std::size_t i = 0; i < corridors.size(); ++i) {
    piano_model::HandCorridor c = corridors[i];
    if (!finite(c)) {
      ++r.dropped;
      r.notes.push_back(line("corridor %zu dropped: non-finite value", i));
      continue;
    }
    if (c.start_s > c.end_s || c.lo_mm > c.hi_mm) {
      if (c.start_s > c.end_s) std::swap(c.start_s, c.end_s);
      if (c.lo_mm > c.hi_mm) std::swap(c.lo_mm, c.hi_mm);
      ++r.sanitized;
      r.notes.push_back(line("corridor %zu at %.3f s: reversed bounds swapped", i, c.start_s));
    }
    items.push_back({c, i});
  }
  const auto by_start = [](const Item& a, const Item& b) { return a.c.start_s < b.c.start_s; };
  if (!std::is_sorted(items.begin(), items.end(), by_start)) {
    std::stable_sort(items.begin(), items.end(), by_start);
    ++r.sanitized;
    r.notes.push_back("corridors sorted by start time");
  }
  for (std::size_t k = 1; k < items.size(); ++k) {
    piano_model::HandCorridor& prev = items[k - 1].c;
    if (prev.end_s > items[k].c.start_s) {
      prev.end_s = std::max(prev.start_s, items[k].c.start_s);
      ++r.sanitized;
      r.notes.push_back(line("corridor %zu overlaps the next in time: end cut to %.3f s",
                             items[k - 1].origin, prev.end_s));
    }
  }
  return items;
}

// Kind 1: open a transition gap at every touching pair with disjoint ranges.
void open_jumps(std::vector<Item>& items, const RepairOptions& options, CorridorRepair& r) {
  const std::size_t n = items.size();
  std::vector<double> trim_start(n, 0.0);
  std::vector<double> trim_end(n, 0.0);
  const auto trim_of = [&](const piano_model::HandCorridor& c) {
    return std::min(options.max_trim_s, options.max_trim_fraction * (c.end_s - c.start_s));
  };
  for (std::size_t k = 0; k + 1 < n; ++k) {
    const piano_model::HandCorridor& a = items[k].c;
    const piano_model::HandCorridor& b = items[k + 1].c;
    if (a.end_s != b.start_s || !disjoint(a, b)) continue;
    const double ta = trim_of(a);
    const double tb = trim_of(b);
    if (ta + tb <= 0.0) continue;  // both zero-length: left to the final pass
    trim_end[k] = ta;
    trim_start[k + 1] = tb;
    ++r.jumps;
    const double distance = a.hi_mm < b.lo_mm ? b.lo_mm - a.hi_mm : a.lo_mm - b.hi_mm;
    r.notes.push_back(
        line("jump between corridors %zu and next at %.3f s: %.1f mm in a %.1f ms gap",
             items[k].origin, a.end_s, distance, 1000.0 * (ta + tb)));
  }
  for (std::size_t k = 0; k < n; ++k) {
    piano_model::HandCorridor& c = items[k].c;
    const double start = c.start_s + trim_start[k];
    c.end_s = std::max(start, c.end_s - trim_end[k]);  // rounding must not reverse it
    c.start_s = start;
  }
}

// Last resort, mirroring corridor_portals' merge: a corridor whose start or end meets the
// previous portal at the same instant with an empty intersection is dropped.
std::vector<Item> drop_unopenable(std::vector<Item> items, CorridorRepair& r) {
  struct PortalTail {
    bool any = false;
    double t = 0, lo = 0, hi = 0;
  } tail;
  const auto add = [&tail](double t, double lo, double hi) {
    if (tail.any && tail.t == t) {
      tail.lo = std::max(tail.lo, lo);
      tail.hi = std::min(tail.hi, hi);
      return tail.lo <= tail.hi;
    }
    tail = {true, t, lo, hi};
    return true;
  };
  std::vector<Item> kept;
  kept.reserve(items.size());
  for (const Item& item : items) {
    const PortalTail saved = tail;
    const piano_model::HandCorridor& c = item.c;
    if (add(c.start_s, c.lo_mm, c.hi_mm) && add(c.end_s, c.lo_mm, c.hi_mm)) {
      kept.push_back(item);
      continue;
    }
    tail = saved;
    ++r.dropped;
    r.notes.push_back(line("corridor %zu at %.3f s dropped: jump with no time to open a gap",
                           item.origin, c.start_s));
  }
  return kept;
}

}  // namespace

CorridorRepair repair_corridors(std::span<const piano_model::HandCorridor> corridors,
                                const RepairOptions& options) {
  CorridorRepair r;
  std::vector<Item> items = sanitize(corridors, r);
  open_jumps(items, options, r);
  items = drop_unopenable(std::move(items), r);
  r.corridors.reserve(items.size());
  r.origin.reserve(items.size());
  for (const Item& item : items) {
    r.corridors.push_back(item.c);
    r.origin.push_back(item.origin);
  }
  return r;
}

}  // namespace tutti::piano_performance
