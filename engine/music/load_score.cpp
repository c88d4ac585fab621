// SPDX-License-Identifier: MIT
#include <tutti/music/load_score.hpp>

#include <algorithm>
#include <cctype>
#include <string_view>

#include <tutti/core/file_io.hpp>
#include <tutti/music/midi/midi_reader.hpp>
#include <tutti/music/musicxml/musicxml_reader.hpp>
#include <tutti/music/pig/pig_format.hpp>

namespace tutti::music {

const char* format_name(ScoreFormat format) {
  switch (format) {
    case ScoreFormat::midi:
      return "MIDI";
    case ScoreFormat::musicxml:
      return "MusicXML";
    case ScoreFormat::pig:
      return "PIG";
  }
  return "unknown";
}

namespace {

bool starts_with(std::span<const std::uint8_t> bytes, std::string_view magic) {
  return bytes.size() >= magic.size() &&
         std::equal(magic.begin(), magic.end(), bytes.begin(),
                    [](char m, std::uint8_t b) { return static_cast<std::uint8_t>(m) == b; });
}

std::string lower_extension(const std::filesystem::path& path) {
  std::string ext = path.extension().string();
  std::transform(ext.begin(), ext.end(), ext.begin(),
                 [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  return ext;
}

}  // namespace

std::optional<ScoreFormat> detect_score_format(std::span<const std::uint8_t> bytes,
                                               const std::filesystem::path& path) {
  if (starts_with(bytes, "MThd") || starts_with(bytes, "RIFF")) return ScoreFormat::midi;
  if (starts_with(bytes, "PK\x03\x04")) return ScoreFormat::musicxml;
  std::size_t first = 0;
  if (starts_with(bytes, "\xEF\xBB\xBF")) first = 3;  // UTF-8 byte order mark
  while (first < bytes.size() && std::isspace(bytes[first])) ++first;
  if (first < bytes.size() && bytes[first] == '<') return ScoreFormat::musicxml;
  if (first + 1 < bytes.size() && bytes[first] == '/' && bytes[first + 1] == '/') {
    return ScoreFormat::pig;
  }
  const std::string ext = lower_extension(path);
  if (ext == ".mid" || ext == ".midi" || ext == ".kar" || ext == ".rmi" || ext == ".smf") {
    return ScoreFormat::midi;
  }
  if (ext == ".xml" || ext == ".musicxml" || ext == ".mxl") return ScoreFormat::musicxml;
  if (ext == ".txt" || ext == ".pig") return ScoreFormat::pig;
  return std::nullopt;
}

Result<Score> load_score(const std::filesystem::path& path) {
  auto bytes = read_file_bytes(path);
  if (!bytes) return bytes.error();
  const std::string name = path.string();
  const auto format = detect_score_format(*bytes, path);
  if (!format) {
    if (bytes->empty()) return Error{name + ": empty file"};
    return Error{name + ": not a MIDI, MusicXML or PIG file (unrecognised content)"};
  }
  switch (*format) {
    case ScoreFormat::midi:
      return read_midi(*bytes, name);
    case ScoreFormat::musicxml:
      return read_musicxml(*bytes, name);
    case ScoreFormat::pig:
      return read_pig(std::string_view(reinterpret_cast<const char*>(bytes->data()), bytes->size()),
                      name);
  }
  return Error{name + ": unknown format"};
}

}  // namespace tutti::music
