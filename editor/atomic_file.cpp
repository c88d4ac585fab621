// SPDX-License-Identifier: MIT
#include <tutti/editor/atomic_file.hpp>

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <chrono>
#include <cstring>
#include <thread>

namespace tutti::editor {
namespace {

namespace fs = std::filesystem;

Error failure(const fs::path& path, const std::string& what) {
  return Error{path.filename().string() + ": cannot save: " + what};
}

std::string errno_text() { return std::strerror(errno); }

Status write_all(int fd, std::string_view contents) {
  while (!contents.empty()) {
    const ssize_t n = ::write(fd, contents.data(), contents.size());
    if (n < 0) {
      if (errno == EINTR) continue;
      return Error{errno_text()};
    }
    contents.remove_prefix(static_cast<std::size_t>(n));
  }
  return Status::success();
}

// Writes `contents` to `path` (created or truncated) and flushes it to the disk.
Status write_synced(const fs::path& path, std::string_view contents, mode_t mode) {
  const int fd = ::open(path.c_str(), O_WRONLY | O_CREAT | O_TRUNC | O_CLOEXEC, mode);
  if (fd < 0) return Error{errno_text()};
  Status written = write_all(fd, contents);
  if (written && ::fsync(fd) != 0) written = Error{errno_text()};
  if (::close(fd) != 0 && written) written = Error{errno_text()};
  return written;
}

void sync_directory(const fs::path& dir) {
  const int fd = ::open(dir.empty() ? "." : dir.c_str(), O_RDONLY | O_DIRECTORY | O_CLOEXEC);
  if (fd < 0) return;  // best effort: the rename itself is already atomic
  ::fsync(fd);
  ::close(fd);
}

// The current file's contents become <file>.bak, atomically, without touching the file.
Status keep_backup(const fs::path& path) {
  const fs::path backup = backup_path(path);
  fs::path staging = backup;
  staging += ".new";
  ::unlink(staging.c_str());
  if (::link(path.c_str(), staging.c_str()) != 0) {
    // No hard links here (some network or FAT file systems): copy, flushed.
    std::error_code ec;
    fs::copy_file(path, staging, fs::copy_options::overwrite_existing, ec);
    if (ec) return Error{"backup: " + ec.message()};
    const int fd = ::open(staging.c_str(), O_RDONLY | O_CLOEXEC);
    if (fd >= 0) {
      ::fsync(fd);
      ::close(fd);
    }
  }
  if (::rename(staging.c_str(), backup.c_str()) != 0) return Error{"backup: " + errno_text()};
  return Status::success();
}

}  // namespace

fs::path backup_path(const fs::path& path) {
  fs::path backup = path;
  backup += ".bak";
  return backup;
}

Status write_file_atomically(const fs::path& path, std::string_view contents,
                             const AtomicWriteOptions& options) {
  const fs::path dir = path.parent_path();
  const fs::path temporary = dir / ("." + path.filename().string() + ".saving");
  mode_t mode = 0644;
  struct stat existing {};
  const bool exists = ::stat(path.c_str(), &existing) == 0;
  if (exists) mode = existing.st_mode & 07777;
  if (Status s = write_synced(temporary, contents, mode); !s) {
    ::unlink(temporary.c_str());
    return failure(path, s.error().message);
  }
  if (exists && options.keep_backup) {
    if (Status s = keep_backup(path); !s) {
      ::unlink(temporary.c_str());
      return failure(path, s.error().message);
    }
  }
  if (options.pause_before_rename_ms > 0) {
    std::this_thread::sleep_for(std::chrono::milliseconds(options.pause_before_rename_ms));
  }
  if (::rename(temporary.c_str(), path.c_str()) != 0) {
    const std::string why = errno_text();
    ::unlink(temporary.c_str());
    return failure(path, why);
  }
  sync_directory(dir);
  return Status::success();
}

}  // namespace tutti::editor
