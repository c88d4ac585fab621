// SPDX-License-Identifier: MIT
#include <tutti/cli/sync_report.hpp>

#include <tutti/audio/energy_rise.hpp>

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>

#include <tutti/audio/attack_time.hpp>
#include <tutti/components/note.hpp>
#include <tutti/components/performer.hpp>
#include <tutti/stage/contact_detector.hpp>

namespace tutti::cli {
namespace {

std::string performer_name(const ecs::World& world, ecs::Entity entity) {
  const auto* performer = world.try_get<components::Performer>(entity);
  return performer != nullptr ? performer->name : std::string();
}

// Whether each player's sound is struck: every note they play is of a part whose General MIDI
// program is (a piano's; an organ's is blown), as the attack compensation hears it.
std::map<std::uint64_t, bool> players_struck(const stage::Stage& stage, ecs::World& world) {
  std::map<std::uint64_t, bool> struck;
  world.view<const components::Note>().each([&](const components::Note& note) {
    if (note.performer.is_null() || note.score < 0 || note.score_index < 0) return;
    const music::Score& score = stage.scores()[static_cast<std::size_t>(note.score)];
    const music::Note& written = score.notes[static_cast<std::size_t>(note.score_index)];
    const bool part_struck =
        written.part >= 0 && static_cast<std::size_t>(written.part) < score.parts.size() &&
        audio::is_struck_program(score.parts[static_cast<std::size_t>(written.part)].program);
    const auto [it, first] = struck.try_emplace(note.performer.bits(), part_struck);
    if (!first) it->second = it->second && part_struck;
  });
  return struck;
}

}  // namespace

std::vector<Contact> sample_contacts(const stage::Stage& stage, double from_s, double to_s,
                                     double step_s) {
  std::vector<Contact> contacts;
  if (!(step_s > 0.0) || !(to_s > from_s)) return contacts;
  stage::StageContext context = stage.make_context();
  const std::map<std::uint64_t, bool> struck_players = players_struck(stage, context.world());
  const ecs::World& world = context.world();
  for (const stage::Stop& stop :
       stage::detect_stops(stage, context, {from_s, to_s, step_s, false})) {
    if (!stop.sounding) continue;  // a valve let go or a slide come to rest in a rest
    if (stop.kind->sync_label.empty()) continue;  // no sound starts (a key coming back up)
    const auto struck = struck_players.find(stop.performer.bits());
    contacts.push_back({stop.t_s, stop.kind, performer_name(world, stop.performer),
                        struck != struck_players.end() && struck->second, stop.value});
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
    // A struck sound (a piano's string) is heard where its energy jumps, as the attack
    // compensation places struck notes (audio/attack_time.hpp); blown notes (an organ's pipe, a
    // trumpet's) keep the detector's point.
    double heard = detected[best];
    const bool struck = std::all_of(e.contacts.begin(), e.contacts.end(),
                                    [](const Contact* c) { return c->struck; });
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

}  // namespace tutti::cli
