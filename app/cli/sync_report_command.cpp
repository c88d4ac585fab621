// SPDX-License-Identifier: MIT
#include <tutti/cli/sync_report_command.hpp>

#include <algorithm>
#include <cmath>
#include <nlohmann/json.hpp>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <memory>
#include <ostream>
#include <string>

#include <tutti/core/exit_codes.hpp>
#include <tutti/cli/frame_range.hpp>
#include <tutti/cli/scene_audio.hpp>
#include <tutti/cli/sync_report.hpp>
#include <tutti/audio/wav_file.hpp>
#include <tutti/cli/stage_scene.hpp>

namespace tutti::cli {
namespace {

std::string format(const char* pattern, double value) {
  char buffer[64];
  std::snprintf(buffer, sizeof buffer, pattern, value);
  return buffer;
}

std::string kinds_of(const SyncMatch& match) {
  std::string text;
  for (const Contact* c : match.contacts) {
    if (!text.empty()) text += ", ";
    text += c->performer + " " + std::string(c->kind->sync_label);
    if (c->detail >= 0) text += " " + std::to_string(c->detail);
  }
  return text;
}

}  // namespace

int run_sync_report(const SyncReportOptions& o, std::ostream& out, std::ostream& err) {
  const Fail fail{err};
  if (!(o.tempo >= 0.1 && o.tempo <= 4.0)) return fail("--tempo: must be in [0.1, 4]");
  if (!(o.step_ms >= 0.05 && o.step_ms <= 10.0)) return fail("--step-ms: must be in [0.05, 10]");
  if (!(o.tolerance_ms >= 1.0 && o.tolerance_ms <= 500.0)) {
    return fail("--tolerance-ms: must be in [1, 500]");
  }
  auto built = stage_scene_file(o.scene, o.assets);
  if (!built) return fail(built.error());
  stage::Stage& stage = **built;
  const scene::Scene* scene = &stage.scene();

  const int fps = scene->output.fps;
  const std::int64_t frames = frame_count(0.0, (stage.end_s() - stage.start_s()) / o.tempo, fps);
  SceneAudioOptions audio_options;
  audio_options.sound_font = o.soundfont;
  audio_options.tempo_factor = o.tempo;
  audio_options.compensate_attacks = o.compensate_attacks;
  auto audio = render_scene_audio(stage, fps, 0, frames, audio_options);
  if (!audio) return fail(audio.error());
  if (!o.wav.empty()) {
    if (Status s = audio::write_wav(o.wav, *audio); !s) return fail(s.error());
  }

  SyncOptions sync;
  sync.step_s = o.step_ms / 1000.0;
  sync.tolerance_s = o.tolerance_ms / 1000.0;
  sync.tempo_factor = o.tempo;
  const std::vector<Contact> contacts =
      sample_contacts(stage, stage.start_s(), stage.end_s(), sync.step_s);
  const SyncFigures f = measure_sync(contacts, *audio, stage.start_s(), sync);
  std::vector<double> signed_ms;
  std::vector<double> abs_ms;
  for (const SyncMatch& m : f.matches) {
    signed_ms.push_back(m.offset_ms());
    abs_ms.push_back(std::abs(m.offset_ms()));
  }
  std::sort(signed_ms.begin(), signed_ms.end());
  std::sort(abs_ms.begin(), abs_ms.end());
  const auto at = [](const std::vector<double>& sorted, double p) {
    if (sorted.empty()) return 0.0;
    return sorted[static_cast<std::size_t>(std::ceil(p * static_cast<double>(sorted.size() - 1)))];
  };
  const double median_ms = at(signed_ms, 0.5);
  const double p95_abs_ms = at(abs_ms, 0.95);
  if (o.json) {
    nlohmann::json doc;
    doc["scene"] = scene->source;
    doc["contacts"] = f.contacts;
    doc["expected"] = f.expected;
    doc["detected"] = f.detected;
    doc["median_ms"] = median_ms;
    doc["p95_abs_ms"] = p95_abs_ms;
    doc["mean_abs_ms"] = f.mean_abs_ms;
    doc["max_abs_ms"] = f.max_abs_ms;
    doc["mean_signed_ms"] = f.mean_signed_ms;
    doc["attack_compensation"] = o.compensate_attacks;
    doc["matches"] = nlohmann::json::array();
    for (const SyncMatch& m : f.matches) {
      nlohmann::json contacts_json = nlohmann::json::array();
      for (const Contact* c : m.contacts) {
        contacts_json.push_back({{"performer", c->performer},
                                 {"kind", c->kind->sync_label},
                                 {"detail", c->detail},
                                 {"time_s", c->time_s}});
      }
      doc["matches"].push_back({{"contact_s", m.contact_s},
                                {"onset_s", m.onset_s},
                                {"offset_ms", m.offset_ms()},
                                {"contacts", contacts_json}});
    }
    doc["unmatched_expected_s"] = f.unmatched_expected_s;
    doc["unmatched_detected_s"] = f.unmatched_detected_s;
    // Audio sample 0 is this music time (the WAV written by --wav starts there).
    doc["audio_start_s"] = stage.start_s();
    out << doc.dump(2) << "\n";
    return kExitOk;
  }

  out << "sync report: " << scene->source << "\n";
  out << "  contacts (animation): " << f.contacts << " events, " << f.expected
      << " expected onsets (merged within " << sync.merge_s * 1000.0 << " ms)\n";
  out << "  onsets (audio):       " << f.detected << " detected\n";
  out << "  matched:              " << f.matches.size() << " (within ±" << o.tolerance_ms
      << " ms); " << f.unmatched_expected_s.size() << " contacts without a sound, "
      << f.unmatched_detected_s.size() << " sounds without a contact\n";
  out << "  offset (sound − contact): mean |" << format("%.2f", f.mean_abs_ms) << "| ms, max |"
      << format("%.2f", f.max_abs_ms) << "| ms, mean " << format("%+.2f", f.mean_signed_ms)
      << " ms, median " << format("%+.2f", median_ms) << " ms, p95 |" << format("%.2f", p95_abs_ms)
      << "| ms\n";
  std::vector<const SyncMatch*> worst;
  for (const SyncMatch& m : f.matches) worst.push_back(&m);
  std::stable_sort(worst.begin(), worst.end(), [](const SyncMatch* a, const SyncMatch* b) {
    return std::abs(a->offset_ms()) > std::abs(b->offset_ms());
  });
  worst.resize(std::min<std::size_t>(worst.size(), static_cast<std::size_t>(std::max(o.worst, 0))));
  for (const SyncMatch* m : worst) {
    out << "    " << format("%8.3f", m->contact_s) << " s  " << format("%+6.2f", m->offset_ms())
        << " ms  " << kinds_of(*m) << "\n";
  }
  if (!f.unmatched_expected_s.empty()) {
    out << "  contacts without a sound at:";
    for (std::size_t i = 0; i < f.unmatched_expected_s.size() && i < 12; ++i) {
      out << " " << format("%.3f", f.unmatched_expected_s[i]);
    }
    out << (f.unmatched_expected_s.size() > 12 ? " ..." : "") << " s\n";
  }
  const double heard =
      f.expected == 0 ? 0.0
                      : static_cast<double>(f.matches.size()) / static_cast<double>(f.expected);
  const bool met = !f.matches.empty() && f.mean_abs_ms <= kSyncGoalMeanMs &&
                   f.max_abs_ms <= kSyncGoalMaxMs && heard >= kSyncGoalHeard;
  out << "  goal (mean ≤ " << kSyncGoalMeanMs << " ms, max ≤ " << format("%.2f", kSyncGoalMaxMs)
      << " ms, ≥ " << format("%.0f", kSyncGoalHeard * 100.0)
      << " % of contacts heard): " << (met ? "met" : "missed") << " ("
      << format("%.0f", heard * 100.0) << " % heard)\n";
  return o.check && !met ? kExitSyncGoalMissed : kExitOk;
}

void register_sync_report_command(Commands& commands) {
  // The options, and the flags that turn one of them off (applied when the command runs).
  struct State {
    SyncReportOptions options;
    bool no_attack_compensation = false;
  };
  auto state = std::make_shared<State>();
  Command& command = commands.add(
      "sync-report",
      "How far the sound is from the picture: note onsets detected in the rendered audio against "
      "the animation's contact times (key bottom, valve down, slide arrives, tongue)");
  command.option("SCENE", state->options.scene, "scene file").required();
  command.option("--assets", state->options.assets, "folder of the generated .glb assets");
  command.option("--soundfont", state->options.soundfont,
                 "General MIDI .sf2 (default: $TUTTI_SOUNDFONT, then Debian's)");
  command.option("--wav", state->options.wav, "also write the analysed audio (WAV)");
  command.option("--tempo", state->options.tempo, "practice tempo, 0.1..4");
  command.option("--step-ms", state->options.step_ms, "animation sampling step (default 0.5)");
  command.option("--tolerance-ms", state->options.tolerance_ms, "furthest match (default 50)");
  command.option("--worst", state->options.worst, "list this many largest offsets (default 5)");
  command.flag("--no-attack-compensation", state->no_attack_compensation,
               "every note at its score time, not early by its sample's attack");
  command.flag("--check", state->options.check, "exit 1 unless mean <= 5 ms and max <= 16.67 ms");
  command.flag("--json", state->options.json,
               "the figures and every match (contact and onset times) as JSON on stdout");
  command.on_run([state](std::ostream& out, std::ostream& err) {
    state->options.compensate_attacks = !state->no_attack_compensation;
    return run_sync_report(state->options, out, err);
  });
}

}  // namespace tutti::cli
