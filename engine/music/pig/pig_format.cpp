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

// "3", "-2", "3_1", "-4_-1". Returns false on anything else.
bool parse_finger(std::string_view text, int& strike, int& hold) {
  hold = 0;
  const auto underscore = text.find('_');
  if (!parse_int(text.substr(0, underscore), strike)) return false;
  if (underscore != std::string_view::npos && !parse_int(text.substr(underscore + 1), hold)) {
    return false;
  }
  auto valid = [](int f) { return f >= -5 && f <= 5; };
  return valid(strike) && valid(hold);
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
    if (!parse_int(fields[4], on_velocity) || on_velocity < 0 || on_velocity > 127) {
      return fail("bad onset velocity '" + std::string(fields[4]) + "'");
    }
    if (!parse_int(fields[5], off_velocity) || off_velocity < 0 || off_velocity > 127) {
      return fail("bad offset velocity '" + std::string(fields[5]) + "'");
    }
    if (!parse_int(fields[6], channel) || (channel != 0 && channel != 1)) {
      return fail("channel must be 0 (right hand) or 1 (left hand), got '" +
                  std::string(fields[6]) + "'");
    }
    int strike = 0;
    int hold = 0;
    if (!parse_finger(fields[7], strike, hold)) {
      return fail("bad finger '" + std::string(fields[7]) + "' (expected 1..5, -1..-5 or a_b)");
    }
    note.pitch = *key;
    note.onset_ticks = to_ticks(onset);
    note.offset_ticks = to_ticks(offset);
    note.velocity = on_velocity == 0 ? 64 : on_velocity;
    note.release_velocity = off_velocity;
    note.part = channel;
    note.channel = channel;
    note.hand = channel == 0 ? Hand::right : Hand::left;
    note.finger = std::abs(strike);
    note.finger_substitute = std::abs(hold);
    note.source_index = line_number - 1;
    score.notes.push_back(note);
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

std::string write_pig(const Score& score) {
  std::ostringstream out;
  out.imbue(std::locale::classic());
  out << "//Version: PigletFormat 1.0 (written by tutti from " << score.source << ")\n";
  out.setf(std::ios::fixed);
  out.precision(6);
  int id = 0;
  for (const Note& note : score.notes) {
    const bool left = hand_of(score, note) == Hand::left;
    const int sign = left ? -1 : 1;
    out << id++ << '\t' << note.onset_s << '\t' << note.offset_s << '\t' << pitch_name(note.pitch)
        << '\t' << note.velocity << '\t' << note.release_velocity << '\t' << (left ? 1 : 0) << '\t'
        << sign * note.finger;
    if (note.finger_substitute != 0) out << '_' << sign * note.finger_substitute;
    out << '\n';
  }
  return out.str();
}

Status write_pig_file(const Score& score, const std::filesystem::path& path) {
  return write_file_atomically(path, write_pig(score));
}

}  // namespace tutti::music
