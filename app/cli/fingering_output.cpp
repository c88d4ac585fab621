// SPDX-License-Identifier: MIT
#include <tutti/cli/fingering_output.hpp>

#include <charconv>
#include <cstdio>
#include <map>
#include <nlohmann/json.hpp>
#include <utility>

#include <tutti/music/midi/midi_writer.hpp>
#include <tutti/music/pitch.hpp>

namespace tutti::cli {
namespace {

const char* hand_name(music::Hand hand) {
  switch (hand) {
    case music::Hand::right:
      return "right";
    case music::Hand::left:
      return "left";
    case music::Hand::unknown:
      break;
  }
  return "unknown";
}

nlohmann::ordered_json path_json(const spline_motion::PathReport& r) {
  return {{"violating_corridors", r.violating_corridors},
          {"worst_violation_mm", r.worst_violation_mm},
          {"peak_speed_mm_per_s", r.peak_speed_mm_per_s},
          {"peak_acceleration_mm_per_s2", r.peak_acceleration_mm_per_s2}};
}

nlohmann::ordered_json hand_json(const piano_performance::HandReport& h) {
  return {{"notes", h.notes},
          {"events", h.events},
          {"diagnostics", h.diagnostics},
          {"repairs",
           {{"jumps", h.repair.jumps},
            {"sanitized", h.repair.sanitized},
            {"dropped", h.repair.dropped}}},
          {"path_error", h.path_error},
          {"violations_planned_corridors", path_json(h.against_used)},
          {"violations_original_corridors", path_json(h.against_original)}};
}

}  // namespace

music::Score fingered_score(const music::Score& score, const fingering_planner::ScorePlan& plan) {
  music::Score out = score;
  for (std::size_t i = 0; i < out.notes.size(); ++i) {
    out.notes[i].finger = i < plan.fingers.size() ? plan.fingers[i] : 0;
    out.notes[i].finger_substitute = 0;
    out.notes[i].finger_sequence.clear();
    if (i < plan.hands.size()) out.notes[i].hand = plan.hands[i];
  }
  return out;
}

std::string fingering_json(const music::Score& fingered, const piano_performance::PerformanceReport& r) {
  nlohmann::ordered_json notes = nlohmann::ordered_json::array();
  for (std::size_t i = 0; i < fingered.notes.size(); ++i) {
    const music::Note& n = fingered.notes[i];
    notes.push_back({{"index", i},
                     {"pitch", n.pitch},
                     {"onset_s", n.onset_s},
                     {"offset_s", n.offset_s},
                     {"hand", hand_name(n.hand)},
                     {"finger", n.finger}});
  }
  nlohmann::ordered_json doc = {
      {"file", fingered.source},
      {"smoothing", spline_motion::to_string(r.smoothing)},
      {"notes", std::move(notes)},
      {"hands", {{"right", hand_json(r.right)}, {"left", hand_json(r.left)}}}};
  return doc.dump(2) + "\n";
}

std::string fingering_listing(const music::Score& fingered) {
  std::string text = "    #   onset_s  key   hand   finger\n";
  char line[96];
  for (std::size_t i = 0; i < fingered.notes.size(); ++i) {
    const music::Note& n = fingered.notes[i];
    std::snprintf(line, sizeof line, "%5zu %9.3f  %-4s  %-5s  %d\n", i, n.onset_s,
                  music::pitch_name(n.pitch).c_str(), hand_name(n.hand), n.finger);
    text += line;
  }
  return text;
}

std::string finger_label(music::Hand hand, int finger, int key) {
  if (hand == music::Hand::unknown || finger < 1 || finger > 5) return "";
  return std::string(hand == music::Hand::right ? "RH" : "LH") + std::to_string(finger) + ":" +
         std::to_string(key);
}

std::optional<FingerLabel> parse_finger_label(std::string_view text) {
  // Exactly "RH" | "LH", one digit 1..5, ':', a key 0..127.
  if (text.size() < 5 || text[1] != 'H' || text[3] != ':') return std::nullopt;
  FingerLabel label;
  if (text[0] == 'R') {
    label.hand = music::Hand::right;
  } else if (text[0] == 'L') {
    label.hand = music::Hand::left;
  } else {
    return std::nullopt;
  }
  if (text[2] < '1' || text[2] > '5') return std::nullopt;
  label.finger = text[2] - '0';
  const char* first = text.data() + 4;
  const char* last = text.data() + text.size();
  const auto [end, ec] = std::from_chars(first, last, label.key);
  if (ec != std::errc{} || end != last || label.key < 0 || label.key > 127) return std::nullopt;
  return label;
}

static bool is_finger_label(const music::TextEvent& text) {
  return text.kind == music::TextKind::lyric && parse_finger_label(text.text).has_value();
}

int apply_finger_labels(music::Score& score) {
  std::map<std::pair<std::int64_t, int>, std::vector<std::size_t>> unfingered;  // (tick, key)
  for (std::size_t i = 0; i < score.notes.size(); ++i) {
    if (score.notes[i].finger == 0) {
      unfingered[{score.notes[i].onset_ticks, score.notes[i].pitch}].push_back(i);
    }
  }
  int applied = 0;
  for (const music::TextEvent& text : score.texts) {
    if (text.kind != music::TextKind::lyric) continue;
    const auto label = parse_finger_label(text.text);
    if (!label) continue;
    auto it = unfingered.find({text.tick, label->key});
    if (it == unfingered.end() || it->second.empty()) continue;
    music::Note& note = score.notes[it->second.front()];
    it->second.erase(it->second.begin());
    note.finger = label->finger;
    note.hand = label->hand;
    ++applied;
  }
  return applied;
}

std::vector<std::uint8_t> fingering_midi(const music::Score& fingered) {
  music::Score score = fingered;
  std::erase_if(score.texts, is_finger_label);
  for (const music::Note& n : fingered.notes) {
    const std::string label = finger_label(n.hand, n.finger, n.pitch);
    if (label.empty()) continue;
    music::TextEvent text;
    text.tick = n.onset_ticks;
    text.seconds = n.onset_s;
    text.kind = music::TextKind::lyric;
    text.track = 0;
    text.text = label;
    score.texts.push_back(std::move(text));
  }
  music::finalize_score(score);  // keeps texts sorted by tick, as the writer expects
  return music::write_midi(score);
}

}  // namespace tutti::cli
