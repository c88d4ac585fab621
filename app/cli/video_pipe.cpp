// SPDX-License-Identifier: MIT
#include <tutti/cli/video_pipe.hpp>

#include <fcntl.h>
#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <fstream>
#include <sstream>
#include <vector>

namespace tutti::cli {

Result<std::unique_ptr<VideoPipe>> VideoPipe::open(const std::filesystem::path& path,
                                                   std::uint32_t width, std::uint32_t height,
                                                   int fps, const std::filesystem::path& audio_wav,
                                                   const VideoEncoding& encoding) {
  // A dying ffmpeg must give an error from write(), not kill us with SIGPIPE.
  signal(SIGPIPE, SIG_IGN);
  std::unique_ptr<VideoPipe> pipe_out(new VideoPipe());
  pipe_out->path_ = path;
  pipe_out->log_ = std::filesystem::temp_directory_path() /
                   ("tutti-ffmpeg-" + std::to_string(getpid()) + ".log");
  int fds[2];
  if (pipe(fds) != 0) {
    return Error{path.string() + ": cannot create a pipe to ffmpeg (" + std::strerror(errno) + ")"};
  }
  const std::string size = std::to_string(width) + "x" + std::to_string(height);
  const std::string rate = std::to_string(fps);
  const std::string output = path.string();
  const std::string log = pipe_out->log_.string();
  std::vector<std::string> args = {"ffmpeg", "-nostdin", "-y",       "-loglevel", "error",
                                   "-f",     "rawvideo", "-pix_fmt", "rgba",      "-s",
                                   size,     "-r",       rate,       "-i",        "-"};
  if (audio_wav.empty()) {
    args.push_back("-an");
  } else {
    args.emplace_back("-i");
    args.push_back(audio_wav.string());
    for (const char* a : {"-map", "0:v:0", "-map", "1:a:0", "-c:a", "aac", "-b:a", "192k"}) {
      args.emplace_back(a);
    }
  }
  for (const char* a :
       {"-c:v", "libx264", "-preset", "veryfast", encoding.lossless ? "-qp" : "-crf",
        encoding.lossless ? "0" : "18", "-pix_fmt", "yuv420p", "-movflags", "+faststart"}) {
    args.emplace_back(a);
  }
  if (!encoding.comment.empty()) {
    args.emplace_back("-metadata");
    args.push_back("comment=" + encoding.comment);
  }
  args.push_back(output);
  std::vector<char*> argv;
  for (std::string& a : args) argv.push_back(a.data());
  argv.push_back(nullptr);
  const pid_t pid = fork();
  if (pid < 0) {
    close(fds[0]);
    close(fds[1]);
    return Error{path.string() + ": cannot start ffmpeg (" + std::strerror(errno) + ")"};
  }
  if (pid == 0) {
    dup2(fds[0], STDIN_FILENO);
    close(fds[0]);
    close(fds[1]);
    const int log_fd = ::open(log.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0600);
    if (log_fd >= 0) {
      dup2(log_fd, STDERR_FILENO);
      dup2(log_fd, STDOUT_FILENO);
      close(log_fd);
    }
    execvp("ffmpeg", argv.data());
    _exit(127);
  }
  close(fds[0]);
  pipe_out->fd_ = fds[1];
  pipe_out->pid_ = pid;
  return pipe_out;
}

VideoPipe::~VideoPipe() {
  if (fd_ >= 0 || pid_ > 0) (void)finish();
}

Status VideoPipe::write(std::span<const std::uint8_t> rgba) {
  std::size_t done = 0;
  while (done < rgba.size()) {
    const ssize_t n = ::write(fd_, rgba.data() + done, rgba.size() - done);
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0) {
      Status finished = finish();
      if (finished) return Error{path_.string() + ": ffmpeg stopped taking frames"};
      // Its own error names the file already; a missing ffmpeg stays the machine's lack.
      if (finished.error().code == ErrorCode::environment) return finished;
      return Error{"ffmpeg stopped taking frames: " + finished.error().message};
    }
    done += static_cast<std::size_t>(n);
  }
  return Status::success();
}

Status VideoPipe::finish() {
  if (fd_ >= 0) {
    close(fd_);
    fd_ = -1;
  }
  if (pid_ <= 0) return Status::success();
  int status = 0;
  while (waitpid(pid_, &status, 0) < 0 && errno == EINTR) {
  }
  pid_ = -1;
  std::string message;
  {
    std::ifstream log(log_);
    std::string line;
    while (std::getline(log, line)) {
      if (!line.empty()) message = line;
    }
  }
  std::error_code ignored;
  std::filesystem::remove(log_, ignored);
  if (WIFEXITED(status) && WEXITSTATUS(status) == 127) {
    return Error{path_.string() + ": ffmpeg not found (install the ffmpeg package)",
                 ErrorCode::environment};
  }
  if (!WIFEXITED(status) || WEXITSTATUS(status) != 0) {
    return Error{path_.string() + ": ffmpeg failed" + (message.empty() ? "" : ": " + message)};
  }
  return Status::success();
}

}  // namespace tutti::cli
