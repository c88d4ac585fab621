// SPDX-License-Identifier: MIT
#include <tutti/music/musicxml/mxl_archive.hpp>

#include <zip.h>

#include <algorithm>
#include <array>
#include <cctype>
#include <memory>
#include <optional>
#include <pugixml.hpp>
#include <string_view>

#include <tutti/music/musicxml/xml_text_values.hpp>

namespace tutti::music::musicxml {

namespace {

constexpr std::string_view kContainerPath = "META-INF/container.xml";
constexpr std::size_t kMaxContainerBytes = std::size_t{1} << 20;

struct ArchiveCloser {
  void operator()(zip_t* archive) const { zip_discard(archive); }
};
using Archive = std::unique_ptr<zip_t, ArchiveCloser>;

struct EntryCloser {
  void operator()(zip_file_t* file) const { zip_fclose(file); }
};
using Entry = std::unique_ptr<zip_file_t, EntryCloser>;

bool ends_with_no_case(std::string_view text, std::string_view suffix) {
  if (text.size() < suffix.size()) return false;
  return std::equal(suffix.begin(), suffix.end(), text.end() - static_cast<long>(suffix.size()),
                    [](char a, char b) {
                      return std::tolower(static_cast<unsigned char>(a)) ==
                             std::tolower(static_cast<unsigned char>(b));
                    });
}

bool is_musicxml_entry_name(std::string_view name) {
  return name.rfind("META-INF/", 0) != 0 &&
         (ends_with_no_case(name, ".xml") || ends_with_no_case(name, ".musicxml"));
}

std::string size_text(std::size_t bytes) {
  constexpr std::size_t kMiB = std::size_t{1} << 20;
  if (bytes >= kMiB && bytes % kMiB == 0) return std::to_string(bytes / kMiB) + " MiB";
  return std::to_string(bytes) + " bytes";
}

// Inflates one entry, stopping as soon as it passes `max_bytes` (the size in the zip directory
// may lie, so the count that matters is what actually comes out).
Result<std::string> read_entry(zip_t* archive, zip_uint64_t index, const std::string& source,
                               std::size_t max_bytes) {
  const char* raw_name = zip_get_name(archive, index, 0);
  const std::string name =
      raw_name != nullptr ? one_line(raw_name, 128) : "entry " + std::to_string(index);
  const std::string too_big = source + ": " + name + " inflates to more than " +
                              size_text(max_bytes) + " (refusing a possible zip bomb)";
  zip_stat_t stat;
  zip_stat_init(&stat);
  if (zip_stat_index(archive, index, 0, &stat) == 0 && (stat.valid & ZIP_STAT_SIZE) != 0 &&
      stat.size > max_bytes) {
    return Error{too_big};
  }
  Entry file{zip_fopen_index(archive, index, 0)};
  if (!file) {
    return Error{source + ": cannot open " + name + " in the archive (" + zip_strerror(archive) +
                 ")"};
  }
  std::string content;
  std::array<char, 64 * 1024> chunk{};
  for (;;) {
    const zip_int64_t got = zip_fread(file.get(), chunk.data(), chunk.size());
    if (got < 0) {
      return Error{source + ": cannot inflate " + name + " (" + zip_file_strerror(file.get()) +
                   ")"};
    }
    if (got == 0) break;
    if (content.size() + static_cast<std::size_t>(got) > max_bytes) {
      return Error{too_big};
    }
    content.append(chunk.data(), static_cast<std::size_t>(got));
  }
  return content;
}

// The score named by META-INF/container.xml, if the container exists and names an entry
// that is present.
std::optional<zip_uint64_t> rootfile_from_container(zip_t* archive, const std::string& source) {
  const zip_int64_t container = zip_name_locate(archive, kContainerPath.data(), ZIP_FL_NOCASE);
  if (container < 0) return std::nullopt;
  auto text = read_entry(archive, static_cast<zip_uint64_t>(container), source, kMaxContainerBytes);
  if (!text) return std::nullopt;
  pugi::xml_document doc;
  if (!doc.load_buffer(text->data(), text->size())) return std::nullopt;
  for (pugi::xml_node rootfile : doc.child("container").child("rootfiles").children("rootfile")) {
    const std::string_view media_type = rootfile.attribute("media-type").as_string();
    if (!media_type.empty() && media_type.find("musicxml") == std::string_view::npos) continue;
    const char* path = rootfile.attribute("full-path").as_string();
    const zip_int64_t index = zip_name_locate(archive, path, 0);
    if (index >= 0) return static_cast<zip_uint64_t>(index);
  }
  return std::nullopt;
}

std::optional<zip_uint64_t> first_musicxml_entry(zip_t* archive) {
  const zip_int64_t count = zip_get_num_entries(archive, 0);
  for (zip_int64_t i = 0; i < count; ++i) {
    const char* name = zip_get_name(archive, static_cast<zip_uint64_t>(i), 0);
    if (name != nullptr && is_musicxml_entry_name(name)) return static_cast<zip_uint64_t>(i);
  }
  return std::nullopt;
}

}  // namespace

bool looks_like_zip(std::span<const std::uint8_t> bytes) {
  return bytes.size() >= 4 && bytes[0] == 'P' && bytes[1] == 'K' &&
         ((bytes[2] == 3 && bytes[3] == 4) || (bytes[2] == 5 && bytes[3] == 6));
}

Result<std::string> read_mxl_score(std::span<const std::uint8_t> bytes, const std::string& source,
                                   std::size_t max_entry_bytes) {
  zip_error_t error;
  zip_error_init(&error);
  zip_source_t* buffer = zip_source_buffer_create(bytes.data(), bytes.size(), 0, &error);
  if (buffer == nullptr) {
    const std::string reason = zip_error_strerror(&error);
    zip_error_fini(&error);
    return Error{source + ": not a readable zip archive (" + reason + ")"};
  }
  Archive archive{zip_open_from_source(buffer, ZIP_RDONLY, &error)};
  if (!archive) {
    zip_source_free(buffer);  // still ours: zip_open_from_source only takes it on success
    const std::string reason = zip_error_strerror(&error);
    zip_error_fini(&error);
    return Error{source + ": not a readable zip archive (" + reason + ")"};
  }
  zip_error_fini(&error);

  std::optional<zip_uint64_t> score = rootfile_from_container(archive.get(), source);
  if (!score) score = first_musicxml_entry(archive.get());
  if (!score) return Error{source + ": the archive holds no MusicXML score"};
  return read_entry(archive.get(), *score, source, max_entry_bytes);
}

}  // namespace tutti::music::musicxml
