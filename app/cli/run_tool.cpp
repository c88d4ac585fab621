// SPDX-License-Identifier: MIT
#include <tutti/cli/run_tool.hpp>

#include <fcntl.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <filesystem>
#include <fstream>

namespace tutti::cli {

Result<std::string> run_tool(const std::vector<std::string>& args, const std::string& what) {
  if (args.empty()) return Error{what + ": no program to run"};
  const std::filesystem::path log =
      std::filesystem::temp_directory_path() / ("tutti-tool-" + std::to_string(getpid()) + ".log");
  int fds[2];
  if (pipe(fds) != 0) return Error{what + ": cannot create a pipe (" + std::strerror(errno) + ")"};
  std::vector<std::string> owned = args;
  std::vector<char*> argv;
  for (std::string& a : owned) argv.push_back(a.data());
  argv.push_back(nullptr);
  const std::string log_name = log.string();
  const pid_t pid = fork();
  if (pid < 0) {
    close(fds[0]);
    close(fds[1]);
    return Error{what + ": cannot start " + args[0] + " (" + std::strerror(errno) + ")"};
  }
  if (pid == 0) {
    dup2(fds[1], STDOUT_FILENO);
    close(fds[0]);
    close(fds[1]);
    const int null_in = ::open("/dev/null", O_RDONLY);
    if (null_in >= 0) dup2(null_in, STDIN_FILENO);
    const int log_fd = ::open(log_name.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0600);
    if (log_fd >= 0) dup2(log_fd, STDERR_FILENO);
    execvp(argv[0], argv.data());
    _exit(127);
  }
  close(fds[1]);
  std::string out;
  char buffer[4096];
  constexpr std::size_t kCap = 1 << 20;
  for (;;) {
    const ssize_t n = read(fds[0], buffer, sizeof buffer);
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0) break;
    if (out.size() < kCap) out.append(buffer, static_cast<std::size_t>(n));
  }
  close(fds[0]);
  int status = 0;
  while (waitpid(pid, &status, 0) < 0 && errno == EINTR) {
  }
  std::string message;
  {
    std::ifstream in(log);
    std::string line;
    while (std::getline(in, line)) {
      if (!line.empty()) message = line;
    }
  }
  std::error_code ignored;
  std::filesystem::remove(log, ignored);
  if (WIFEXITED(status) && WEXITSTATUS(status) == 127) {
    return Error{what + ": " + args[0] + " not found (install the ffmpeg package)"};
  }
  if (!WIFEXITED(status) || WEXITSTATUS(status) != 0) {
    return Error{what + ": " + args[0] + " failed" + (message.empty() ? "" : ": " + message)};
  }
  return out;
}

}  // namespace tutti::cli
