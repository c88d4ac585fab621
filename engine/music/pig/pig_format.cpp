// SPDX-License-Identifier: MIT
#include <tutti/music/pig/pig_format.hpp>

#include <charconv>
#include <cmath>
#include <cstdlib>
#include <sstream>
#include <vector>

#include <tutti/core/file_io.hpp>
#include <tutti/music/pitch.hpp>

namespace tutti::music {

namespace {

constexpr int kTicksPerQuarter = 480;
constexpr double kTicksPerSecond = kTicksPerQuarter * 2.0;  // fixed 120 BPM
// Ten hours: longer onsets are a corrupt file, not music.
constexpr double kMaxSeconds = 36000.0;

std::vector<std::string_view> split_fields(std::string_view line) {
  std::vector<std::string_view> fields;
  std::size_t i = 0;
  while (i < line.size()) {
    while (i < line.size() && (line[i] == '\t' || line[i] == ' ')) ++i;
    const std::size_t start = i;
    while (i < line.size() && line[i] != '\t' && line[i] != ' ') ++i;
    if (i > start) fields.push_back(line.substr(start, i - start));
  }
  return fields;
}

bool parse_int(std::string_view text, int& out) {
  const auto [end, ec] = std::from_chars(text.data(), text.data() + text.size(), out);
  return ec == std::errc{} && end == text.data() + text.size();
}

bool parse_seconds(std::string_view text, double& out) {
  // std::from_chars for double is in libstdc++ 11+, locale independent.
  const auto [end, ec] = std::from_chars(text.data(), text.data() + text.size(), out);
  return ec == std::errc{} && end == text.data() + text.size() && std::isfinite(out) &&
         out >= 0.0 && out <= kMaxSeconds;
}

// "3", "-2", "3_1", "-4_-1", "2_4_5": the fingers in order. Returns false on anything else.
bool parse_fingers(std::string_view text, std::vector<int>& fingers) {
  fingers.clear();
  std::size_t start = 0;
  for (;;) {
    const std::size_t underscore = text.find('_', start);
    int finger = 0;
    if (!parse_int(text.substr(start, underscore == std::string_view::npos ? std::string_view::npos
                                                                             : underscore - start),
                   finger) ||
        finger < -5 || finger > 5) {
      return false;
    }
    fingers.push_back(finger);
    if (underscore == std::string_view::npos) return fingers.size() <= 5;
    start = underscore + 1;
  }
}

// A velocity column: 0..127, or -1 for "not recorded" (the PIG dataset's offset velocities).
bool parse_velocity(std::string_view text, int& out) {
  return parse_int(text, out) && out >= -1 && out <= 127;
}

std::int64_t to_ticks(double seconds) {
  return static_cast<std::int64_t>(std::llround(seconds * kTicksPerSecond));
}

}  // namespace

Result<Score> read_pig(std::string_view text, const std::string& source_name) {
  Score score;
  score.source = source_name;
  score.tempo_map = TempoMap::with_ticks_per_quarter(kTicksPerQuarter);
  score.parts.resize(2);
  score.parts[0].id = "right";
  score.parts[0].name = "Right hand";
  score.parts[0].channel = 0;
  score.parts[1].id = "left";
  score.parts[1].name = "Left hand";
  score.parts[1].channel = 1;

  int line_number = 0;
  bool seen_note = false;
  std::size_t pos = 0;
  while (pos < text.size()) {
    std::size_t end = text.find('\n', pos);
    if (end == std::string_view::npos) end = text.size();
    std::string_view line = text.substr(pos, end - pos);
    pos = end + 1;
    ++line_number;
    if (!line.empty() && line.back() == '\r') line.remove_suffix(1);
    if (line.empty() || line.starts_with("//")) continue;

    auto fail = [&](const std::string& reason) {
      return Error{source_name + ": line " + std::to_string(line_number) + ": " + reason};
    };
    for (char c : line) {
      if (static_cast<unsigned char>(c) < 0x09 || c == 0x7f)
        return fail("binary data, not PIG text");
    }
    const auto fields = split_fields(line);
    if (fields.empty()) continue;
    if (fields.size() != 8) {
      return fail("expected 8 fields (id onset offset pitch onVel offVel channel finger), got " +
                  std::to_string(fields.size()));
    }
    Note note;
    double onset = 0.0;
    double offset = 0.0;
    if (!parse_seconds(fields[1], onset))
      return fail("bad onset time '" + std::string(fields[1]) + "'");
    if (!parse_seconds(fields[2], offset))
      return fail("bad offset time '" + std::string(fields[2]) + "'");
    if (offset < onset) return fail("offset before onset");
    const auto key = parse_pitch_name(fields[3]);
    if (!key) return fail("bad pitch '" + std::string(fields[3]) + "'");
    int on_velocity = 0;
    int off_velocity = 0;
    int channel = 0;
    if (!parse_velocity(fields[4], on_velocity)) {
      return fail("bad onset velocity '" + std::string(fields[4]) + "' (0..127, or -1)");
    }
    if (!parse_velocity(fields[5], off_velocity)) {
      return fail("bad offset velocity '" + std::string(fields[5]) + "' (0..127, or -1)");
    }
    if (!parse_int(fields[6], channel) || (channel != 0 && channel != 1)) {
      return fail("channel must be 0 (right hand) or 1 (left hand), got '" +
                  std::string(fields[6]) + "'");
    }
    std::vector<int> fingers;
    if (!parse_fingers(fields[7], fingers)) {
      return fail("bad finger '" + std::string(fields[7]) +
                  "' (expected 1..5, -1..-5, or a substitution a_b or a_b_c)");
    }
    const int strike = fingers.front();
    const int hold = fingers.size() > 1 ? fingers.back() : 0;
    note.pitch = *key;
    note.onset_ticks = to_ticks(onset);
    note.offset_ticks = to_ticks(offset);
    // 0 or -1: no onset velocity recorded (a default); -1: no offset velocity (MIDI's 64).
    note.velocity = on_velocity <= 0 ? 64 : on_velocity;
    note.release_velocity = off_velocity < 0 ? 64 : off_velocity;
    note.part = channel;
    note.channel = channel;
    note.hand = channel == 0 ? Hand::right : Hand::left;
    note.finger = std::abs(strike);
    note.finger_substitute = std::abs(hold);
    if (fingers.size() > 2) {
      for (const int f : fingers) note.finger_sequence.push_back(std::abs(f));
    }
    note.source_index = line_number - 1;
    score.notes.push_back(note);
    // The line as it was up to its finger column (its spacing too: a first field "//x" after a
    // tab is a note, not a comment).
    score.pig_rows.push_back({note.source_index, std::string(line.substr(
                                                     0, static_cast<std::size_t>(fields[7].data() - line.data())))});
    seen_note = true;
  }
  if (!seen_note) return Error{source_name + ": no notes (not a PIG fingering file?)"};
  finalize_score(score);
  return score;
}

Result<Score> read_pig_file(const std::filesystem::path& path) {
  auto bytes = read_file_bytes(path);
  if (!bytes) return bytes.error();
  const std::string_view text(reinterpret_cast<const char*>(bytes->data()), bytes->size());
  return read_pig(text, path.string());
}

namespace {
Hand hand_of(const Score& score, const Note& note) {
  if (note.hand != Hand::unknown) return note.hand;
  if (note.part >= 0 && static_cast<std::size_t>(note.part) < score.parts.size()) {
    const std::string& name = score.parts[static_cast<std::size_t>(note.part)].name;
    if (name.find("eft") != std::string::npos) return Hand::left;
    if (name.find("ight") != std::string::npos) return Hand::right;
  }
  return note.pitch >= 60 ? Hand::right : Hand::left;
}
}  // namespace

namespace {
// The finger column: negative for the left hand, a substitution's fingers joined by '_'.
std::string finger_column(const Score& score, const Note& note) {
  const int sign = hand_of(score, note) == Hand::left ? -1 : 1;
  std::string text;
  if (note.finger_sequence.size() > 2) {
    for (const int f : note.finger_sequence) {
      text += (text.empty() ? "" : "_") + std::to_string(sign * f);
    }
    return text;
  }
  text = std::to_string(sign * note.finger);
  if (note.finger_substitute != 0) text += "_" + std::to_string(sign * note.finger_substitute);
  return text;
}
}  // namespace

std::string write_pig(const Score& score) {
  std::ostringstream out;
  out.imbue(std::locale::classic());
  // Read from PIG: its lines back in their order, ids, times and spellings; only the fingers new.
  if (!score.pig_rows.empty()) {
    std::vector<const Note*> by_line;
    for (const Note& note : score.notes) {
      if (note.source_index < 0) continue;
      const auto line = static_cast<std::size_t>(note.source_index);
      if (by_line.size() <= line) by_line.resize(line + 1, nullptr);
      by_line[line] = &note;
    }
    out << "//Version: PigletFormat 1.0 (fingers written by tutti; the rest as in " << score.source
        << ")\n";
    for (const Score::PigRow& row : score.pig_rows) {
      const auto line = static_cast<std::size_t>(row.line);
      const Note* note = line < by_line.size() ? by_line[line] : nullptr;
      out << row.columns << (note != nullptr ? finger_column(score, *note) : "0") << '\n';
    }
    return out.str();
  }
  out << "//Version: PigletFormat 1.0 (written by tutti from " << score.source << ")\n";
  out.setf(std::ios::fixed);
  out.precision(6);
  int id = 0;
  for (const Note& note : score.notes) {
    const bool left = hand_of(score, note) == Hand::left;
    out << id++ << '\t' << note.onset_s << '\t' << note.offset_s << '\t' << pitch_name(note.pitch)
        << '\t' << note.velocity << '\t' << note.release_velocity << '\t' << (left ? 1 : 0) << '\t'
        << finger_column(score, note) << '\n';
  }
  return out.str();
}

Status write_pig_file(const Score& score, const std::filesystem::path& path) {
  return write_file_atomically(path, write_pig(score));
}

}  // namespace tutti::music
