// SPDX-License-Identifier: MIT
#pragma once
// A minimal zip writer for tests: "stored" (uncompressed) entries, enough to build .mxl
// containers with chosen contents without a zip library in the test.

#include <array>
#include <cstdint>
#include <string>
#include <utility>
#include <vector>

namespace tutti::test {

inline std::uint32_t crc32_of(const std::string& data) {
  static const std::array<std::uint32_t, 256> table = [] {
    std::array<std::uint32_t, 256> t{};
    for (std::uint32_t i = 0; i < 256; ++i) {
      std::uint32_t c = i;
      for (int k = 0; k < 8; ++k) c = (c & 1u) != 0 ? 0xEDB88320u ^ (c >> 1) : c >> 1;
      t[i] = c;
    }
    return t;
  }();
  std::uint32_t crc = 0xFFFFFFFFu;
  for (const char ch : data) {
    crc = table[(crc ^ static_cast<std::uint8_t>(ch)) & 0xFFu] ^ (crc >> 8);
  }
  return crc ^ 0xFFFFFFFFu;
}

// Entries are (name, content); returns the archive's bytes.
inline std::vector<std::uint8_t> make_stored_zip(
    const std::vector<std::pair<std::string, std::string>>& entries) {
  std::vector<std::uint8_t> out;
  auto u16 = [&](std::uint32_t v) {
    out.push_back(static_cast<std::uint8_t>(v & 0xFFu));
    out.push_back(static_cast<std::uint8_t>((v >> 8) & 0xFFu));
  };
  auto u32 = [&](std::uint32_t v) {
    u16(v & 0xFFFFu);
    u16(v >> 16);
  };
  auto bytes = [&](const std::string& s) { out.insert(out.end(), s.begin(), s.end()); };

  std::vector<std::uint32_t> offsets;
  for (const auto& [name, content] : entries) {
    offsets.push_back(static_cast<std::uint32_t>(out.size()));
    u32(0x04034b50u);
    u16(20);  // version needed
    u16(0);   // flags
    u16(0);   // stored
    u16(0);   // time
    u16(0);   // date
    u32(crc32_of(content));
    u32(static_cast<std::uint32_t>(content.size()));
    u32(static_cast<std::uint32_t>(content.size()));
    u16(static_cast<std::uint32_t>(name.size()));
    u16(0);
    bytes(name);
    bytes(content);
  }
  const auto directory_start = static_cast<std::uint32_t>(out.size());
  for (std::size_t i = 0; i < entries.size(); ++i) {
    const auto& [name, content] = entries[i];
    u32(0x02014b50u);
    u16(20);  // made by
    u16(20);  // needed
    u16(0);
    u16(0);
    u16(0);
    u16(0);
    u32(crc32_of(content));
    u32(static_cast<std::uint32_t>(content.size()));
    u32(static_cast<std::uint32_t>(content.size()));
    u16(static_cast<std::uint32_t>(name.size()));
    u16(0);  // extra
    u16(0);  // comment
    u16(0);  // disk
    u16(0);  // internal attributes
    u32(0);  // external attributes
    u32(offsets[i]);
    bytes(name);
  }
  const auto directory_size = static_cast<std::uint32_t>(out.size()) - directory_start;
  u32(0x06054b50u);
  u16(0);
  u16(0);
  u16(static_cast<std::uint32_t>(entries.size()));
  u16(static_cast<std::uint32_t>(entries.size()));
  u32(directory_size);
  u32(directory_start);
  u16(0);
  return out;
}

}  // namespace tutti::test
