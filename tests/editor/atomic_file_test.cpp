// SPDX-License-Identifier: MIT
// Saving never loses the user's file: the contents are either the old or the new ones, even when
// the saving process is killed at a random moment, and the previous version is kept as .bak.
#include <tutti/editor/atomic_file.hpp>

#include <gtest/gtest.h>
#include <signal.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <cstdint>
#include <cstdlib>
#include <thread>

#include "editor_test_support.hpp"

namespace tutti::editor {
namespace {

using test::read_text;
using test::ScratchDir;

TEST(AtomicFile, ReplacesAndKeepsOneBackup) {
  ScratchDir dir;
  const auto file = dir.write("scene.json", "version 1\n");
  ::chmod(file.c_str(), 0600);
  ASSERT_TRUE(write_file_atomically(file, "version 2\n"));
  EXPECT_EQ(read_text(file), "version 2\n");
  EXPECT_EQ(read_text(backup_path(file)), "version 1\n");
  ASSERT_TRUE(write_file_atomically(file, "version 3\n"));
  EXPECT_EQ(read_text(file), "version 3\n");
  EXPECT_EQ(read_text(backup_path(file)), "version 2\n") << "one backup: the previous version";
  struct stat info {};
  ASSERT_EQ(::stat(file.c_str(), &info), 0);
  EXPECT_EQ(info.st_mode & 0777, 0600u) << "the file keeps its permissions";
  // No temporary left behind.
  int files = 0;
  for (const auto& entry : std::filesystem::directory_iterator(dir.path())) {
    (void)entry;
    ++files;
  }
  EXPECT_EQ(files, 2);
}

TEST(AtomicFile, ANewFileHasNoBackup) {
  ScratchDir dir;
  const auto file = dir.path() / "new.json";
  ASSERT_TRUE(write_file_atomically(file, "{}\n"));
  EXPECT_EQ(read_text(file), "{}\n");
  EXPECT_FALSE(std::filesystem::exists(backup_path(file)));
}

TEST(AtomicFile, AnUnwritableFolderIsAOneLineError) {
  const Status s = write_file_atomically("/proc/no_such_dir/scene.json", "{}");
  ASSERT_FALSE(s);
  EXPECT_EQ(s.error().message.rfind("scene.json: cannot save: ", 0), 0u) << s.error().message;
  EXPECT_EQ(s.error().message.find('\n'), std::string::npos);
}

// A child process saves big versions over and over; it is killed (SIGKILL, no clean-up) at a
// different moment each round. Whatever moment: the file is one complete version. Rounds go on
// (up to 120) until at least three kills have landed inside a save: how long a save takes varies
// with the machine's load and the sanitizers, and twelve fixed rounds sometimes had none.
TEST(AtomicFile, KilledDuringSaveTheFileIsOneWholeVersion) {
  ScratchDir dir;
  const std::string old_version = "{\"version\": \"old\"}\n";
  const auto file = dir.write("scene.json", old_version);
  auto version = [](int n) {
    std::string text = "{\"version\": " + std::to_string(n) + ", \"padding\": \"";
    text.append(4u << 20, static_cast<char>('a' + n % 26));  // 4 MiB: a save takes a while
    return text + "\"}\n";
  };
  int killed_mid_save = 0;
  for (int round = 0; round < 120 && (round < 12 || killed_mid_save < 3); ++round) {
    const pid_t child = ::fork();
    ASSERT_GE(child, 0);
    if (child == 0) {
      for (int n = 0;; ++n) {
        if (!write_file_atomically(file, version(n))) ::_exit(3);
      }
    }
    std::this_thread::sleep_for(std::chrono::milliseconds(5 + 7 * (round % 12) + round / 12));
    ::kill(child, SIGKILL);
    int status = 0;
    ::waitpid(child, &status, 0);
    ASSERT_TRUE(WIFSIGNALED(status)) << "the saver was killed, it did not fail";
    const std::string now = read_text(file);
    bool whole = now == old_version;
    const std::string prefix = "{\"version\": ";
    if (!whole && now.rfind(prefix, 0) == 0) {
      whole = now == version(std::atoi(now.c_str() + prefix.size()));
    }
    ASSERT_TRUE(whole) << "round " << round << ": " << now.size() << " bytes, not one version";
    if (std::filesystem::exists(dir.path() / ".scene.json.saving")) ++killed_mid_save;
  }
  // The test is only worth something if some kills landed inside a save.
  EXPECT_GT(killed_mid_save, 0);
}

}  // namespace
}  // namespace tutti::editor
