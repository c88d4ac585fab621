// SPDX-License-Identifier: MIT
#pragma once
// Whole-file reads with a size cap, so a hostile or mistaken input (a 40 GB file, /dev/zero, a
// directory) fails with a clear message instead of exhausting memory.

#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

#include <tutti/core/result.hpp>

namespace tutti {

inline constexpr std::size_t kDefaultMaxFileBytes = std::size_t{256} << 20;  // 256 MiB

// Errors: "<path>: no such file", "<path>: is a directory", "<path>: larger than 256 MiB",
// "<path>: cannot read (<reason>)".
Result<std::vector<std::uint8_t>> read_file_bytes(const std::filesystem::path& path,
                                                  std::size_t max_bytes = kDefaultMaxFileBytes);

// Writes via a temporary file in the same folder, flushed and renamed over the target, so the
// previous content survives a crash mid-write.
Status write_file_atomically(const std::filesystem::path& path, const std::string& content);

}  // namespace tutti
