// SPDX-License-Identifier: MIT
#include <tutti/core/file_io.hpp>

#include <fcntl.h>
#include <unistd.h>

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <fstream>
#include <system_error>

namespace tutti {

namespace fs = std::filesystem;

Result<std::vector<std::uint8_t>> read_file_bytes(const fs::path& path, std::size_t max_bytes) {
  const std::string name = path.string();
  std::error_code ec;
  const auto status = fs::status(path, ec);
  if (ec || !fs::exists(status)) return Error{name + ": no such file"};
  if (fs::is_directory(status)) return Error{name + ": is a directory, not a file"};

  std::ifstream in(path, std::ios::binary);
  if (!in) return Error{name + ": cannot open (" + std::strerror(errno) + ")"};

  // Read in chunks rather than trusting the reported size: pipes and devices report 0.
  std::vector<std::uint8_t> bytes;
  std::vector<char> chunk(std::size_t{1} << 16);
  while (in) {
    in.read(chunk.data(), static_cast<std::streamsize>(chunk.size()));
    const auto got = static_cast<std::size_t>(in.gcount());
    if (bytes.size() + got > max_bytes) {
      return Error{name + ": larger than " + std::to_string(max_bytes >> 20) + " MiB, refused"};
    }
    bytes.insert(bytes.end(), chunk.data(), chunk.data() + got);
  }
  if (in.bad()) return Error{name + ": read failed"};
  return bytes;
}

Status write_file_atomically(const fs::path& path, const std::string& content) {
  const std::string name = path.string();
  fs::path temp = path;
  temp += ".tmp-" + std::to_string(::getpid());
  const int fd = ::open(temp.c_str(), O_WRONLY | O_CREAT | O_TRUNC | O_CLOEXEC, 0644);
  if (fd < 0) return Error{name + ": cannot write (" + std::strerror(errno) + ")"};
  std::size_t written = 0;
  while (written < content.size()) {
    const ssize_t n = ::write(fd, content.data() + written, content.size() - written);
    if (n < 0) {
      if (errno == EINTR) continue;
      const std::string reason = std::strerror(errno);
      ::close(fd);
      ::unlink(temp.c_str());
      return Error{name + ": write failed (" + reason + ")"};
    }
    written += static_cast<std::size_t>(n);
  }
  if (::fsync(fd) != 0 || ::close(fd) != 0) {
    const std::string reason = std::strerror(errno);
    ::unlink(temp.c_str());
    return Error{name + ": write failed (" + reason + ")"};
  }
  if (std::rename(temp.c_str(), path.c_str()) != 0) {
    const std::string reason = std::strerror(errno);
    ::unlink(temp.c_str());
    return Error{name + ": cannot replace (" + reason + ")"};
  }
  return Status::success();
}

}  // namespace tutti
