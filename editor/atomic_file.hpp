// SPDX-License-Identifier: MIT
#pragma once
// Saving without ever losing the user's file: the new contents go to a temporary file beside it,
// are flushed to the disk (fsync), and only then replace the file by rename(2), which is atomic.
// A crash or a kill at any moment leaves either the old file or the new one, never a mix. The
// previous version is kept as "<file>.bak" (a hard link to the old contents, or a copy where
// links are not possible).

#include <filesystem>
#include <string>
#include <string_view>

#include <tutti/core/result.hpp>

namespace tutti::editor {

struct AtomicWriteOptions {
  bool keep_backup = true;  // the replaced version becomes <file>.bak
  // Tests only: wait this long with the new contents written and flushed but not yet renamed
  // into place, so a test can kill the process inside a save.
  int pause_before_rename_ms = 0;
};

// Errors name the file: "quartet.json: cannot save: Permission denied".
Status write_file_atomically(const std::filesystem::path& path, std::string_view contents,
                             const AtomicWriteOptions& options = {});

std::filesystem::path backup_path(const std::filesystem::path& path);  // <file>.bak

}  // namespace tutti::editor
