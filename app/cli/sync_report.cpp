// SPDX-License-Identifier: MIT
#include <tutti/cli/sync_report.hpp>

#include <tutti/audio/energy_rise.hpp>

#include <algorithm>
#include <cmath>
#include <limits>

#include <tutti/components/finger.hpp>
#include <tutti/components/hand.hpp>
#include <tutti/components/instrument.hpp>
#include <tutti/components/mouth.hpp>
#include <tutti/components/performer.hpp>
#include <tutti/components/slide.hpp>
#include <tutti/components/valve.hpp>

namespace tutti::app {
namespace {

constexpr double kFullyDown = 0.999;
constexpr double kFullyUp = 0.001;

// Linear crossing time of `level` between (t0, v0) and (t1, v1).
double crossing(double t0, double v0, double t1, double v1, double level) {
  if (v1 == v0) return t1;
  return t0 + (t1 - t0) * std::clamp((level - v0) / (v1 - v0), 0.0, 1.0);
}

std::string performer_name(const ecs::World& world, ecs::Entity entity, const char* fallback) {
  const auto* performer = world.try_get<components::Performer>(entity);
  return performer != nullptr && !performer->name.empty() ? performer->name : fallback;
}

struct FingerTrack {
  ecs::Entity entity = ecs::Entity::null;
  std::string name;  // the pianist's
  double depth = 0.0;
  std::uint32_t entity_index() const { return entity.index; }
};

struct BrassTrack {
  ecs::Entity performer = ecs::Entity::null;
  ecs::Entity instrument = ecs::Entity::null;
  std::string name;
  std::array<double, components::Valve::kMax> press{};
  bool moving = false;
  bool buzzing = false;
  // Valve releases and slide arrivals wait one sample to see whether the player sounds.
  std::vector<Contact> pending;
  std::uint32_t entity_index() const { return instrument.index; }
};

}  // namespace

const char* contact_kind_name(ContactKind kind) {
  switch (kind) {
    case ContactKind::key_bottom:
      return "key bottom";
    case ContactKind::valve_down:
      return "valve down";
    case ContactKind::valve_up:
      return "valve up";
    case ContactKind::slide_arrives:
      return "slide arrives";
    case ContactKind::tongue:
      return "tongue";
  }
  return "?";
}

std::vector<Contact> sample_contacts(stage::Stage& stage, double from_s, double to_s,
                                     double step_s) {
  std::vector<Contact> contacts;
  if (!(step_s > 0.0) || !(to_s > from_s)) return contacts;
  // Every finger and every instrument on stage, in the order they were spawned.
  ecs::World& world = stage.world();
  std::vector<FingerTrack> fingers;
  world.view<const components::Finger>().each([&](ecs::Entity e, const components::Finger& f) {
    const auto* hand = world.try_get<components::Hand>(f.hand);
    fingers.push_back(
        {e, performer_name(world, hand != nullptr ? hand->performer : ecs::Entity::null, "pianist"),
         0.0});
  });
  std::vector<BrassTrack> brass;
  world.view<const components::Instrument>().each(
      [&](ecs::Entity e, const components::Instrument& instrument) {
        BrassTrack track;
        track.performer = instrument.performer;
        track.instrument = e;
        track.name = performer_name(world, instrument.performer, "");
        brass.push_back(std::move(track));
      });
  const auto by_spawn = [](const auto& a, const auto& b) {
    return a.entity_index() < b.entity_index();
  };
  std::sort(fingers.begin(), fingers.end(), by_spawn);
  std::sort(brass.begin(), brass.end(), by_spawn);

  const auto steps = static_cast<std::int64_t>(std::ceil((to_s - from_s) / step_s));
  double previous_t = from_s;
  for (std::int64_t i = 0; i < steps; ++i) {
    const double t = from_s + static_cast<double>(i) * step_s;
    stage.run({t, step_s}, ecs::Phase::evaluate);
    const bool first = i == 0;
    for (FingerTrack& track : fingers) {
      const auto* finger = world.try_get<components::Finger>(track.entity);
      if (finger == nullptr) continue;
      if (!first && track.depth < kFullyDown && finger->press_depth >= kFullyDown) {
        contacts.push_back({crossing(previous_t, track.depth, t, finger->press_depth, kFullyDown),
                            ContactKind::key_bottom, track.name, finger->key});
      }
      track.depth = finger->press_depth;
    }
    for (BrassTrack& track : brass) {
      const auto* mouth = world.try_get<components::Mouth>(track.performer);
      const auto* valve = world.try_get<components::Valve>(track.instrument);
      const auto* slide = world.try_get<components::Slide>(track.instrument);
      const bool buzzing = mouth != nullptr && mouth->buzzing;
      // Last sample's releases and arrivals happened while the player sounds (or did not).
      if (buzzing && track.buzzing) {
        contacts.insert(contacts.end(), track.pending.begin(), track.pending.end());
      }
      track.pending.clear();
      if (!first && buzzing && !track.buzzing) {
        contacts.push_back({t, ContactKind::tongue, track.name, -1});
      }
      if (valve != nullptr) {
        for (std::size_t v = 0; v < valve->count && v < track.press.size(); ++v) {
          const double now = valve->press[v];
          const double before = track.press[v];
          if (!first && before < kFullyDown && now >= kFullyDown) {
            contacts.push_back({crossing(previous_t, before, t, now, kFullyDown),
                                ContactKind::valve_down, track.name, static_cast<int>(v) + 1});
          } else if (!first && before > kFullyUp && now <= kFullyUp) {
            track.pending.push_back({crossing(previous_t, before, t, now, kFullyUp),
                                     ContactKind::valve_up, track.name, static_cast<int>(v) + 1});
          }
          track.press[v] = now;
        }
      }
      if (slide != nullptr) {
        const bool moving = slide->speed_mm_per_s != 0.0;
        if (!first && track.moving && !moving) {
          track.pending.push_back({t, ContactKind::slide_arrives, track.name, -1});
        }
        track.moving = moving;
      }
      track.buzzing = buzzing;
    }
    previous_t = t;
  }
  std::stable_sort(contacts.begin(), contacts.end(),
                   [](const Contact& a, const Contact& b) { return a.time_s < b.time_s; });
  return contacts;
}

SyncFigures measure_sync(const std::vector<Contact>& contacts, const audio::AudioBuffer& audio,
                         double audio_start_s, const SyncOptions& options) {
  SyncFigures figures;
  figures.contacts = contacts.size();

  // Expected onsets: runs of contacts within merge_s of the run's first.
  struct Expected {
    double time_s;
    std::vector<const Contact*> contacts;
  };
  std::vector<Expected> expected;
  for (const Contact& c : contacts) {
    if (expected.empty() || c.time_s - expected.back().time_s > options.merge_s) {
      expected.push_back({c.time_s, {}});
    }
    expected.back().contacts.push_back(&c);
  }
  figures.expected = expected.size();

  std::vector<double> detected;
  for (const audio::Onset& onset : audio::detect_onsets(audio, options.onsets)) {
    detected.push_back(audio_start_s + onset.time_s * options.tempo_factor);
  }
  figures.detected = detected.size();

  // Each expected onset takes the nearest free detected onset within the tolerance.
  std::vector<bool> used(detected.size(), false);
  for (Expected& e : expected) {
    auto it = std::lower_bound(detected.begin(), detected.end(), e.time_s - options.tolerance_s);
    std::size_t best = detected.size();
    double best_distance = std::numeric_limits<double>::infinity();
    for (; it != detected.end() && *it <= e.time_s + options.tolerance_s; ++it) {
      const auto index = static_cast<std::size_t>(it - detected.begin());
      const double distance = std::abs(*it - e.time_s);
      if (!used[index] && distance < best_distance) {
        best = index;
        best_distance = distance;
      }
    }
    if (best == detected.size()) {
      figures.unmatched_expected_s.push_back(e.time_s);
      continue;
    }
    used[best] = true;
    // A key's sound (a struck string) is heard where its energy jumps, as the attack compensation
    // places struck notes (audio/attack_time.hpp); blown notes keep the detector's point.
    double heard = detected[best];
    const bool struck = std::all_of(e.contacts.begin(), e.contacts.end(), [](const Contact* c) {
      return c->kind == ContactKind::key_bottom;
    });
    if (struck) {
      const double at = (heard - audio_start_s) / options.tempo_factor;
      heard = audio_start_s + audio::steepest_energy_rise_s(audio, at - 0.020, at + 0.003, at) *
                                  options.tempo_factor;
    }
    figures.matches.push_back({e.time_s, heard, std::move(e.contacts)});
  }
  for (std::size_t i = 0; i < detected.size(); ++i) {
    if (!used[i]) figures.unmatched_detected_s.push_back(detected[i]);
  }
  double sum_abs = 0.0, sum = 0.0;
  for (const SyncMatch& m : figures.matches) {
    const double offset = m.offset_ms();
    sum_abs += std::abs(offset);
    sum += offset;
    figures.max_abs_ms = std::max(figures.max_abs_ms, std::abs(offset));
  }
  if (!figures.matches.empty()) {
    figures.mean_abs_ms = sum_abs / static_cast<double>(figures.matches.size());
    figures.mean_signed_ms = sum / static_cast<double>(figures.matches.size());
  }
  return figures;
}

}  // namespace tutti::app
