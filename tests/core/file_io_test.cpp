// SPDX-License-Identifier: MIT
#include <tutti/core/file_io.hpp>

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

#include "testdata.hpp"

namespace tutti {
namespace {

namespace fs = std::filesystem;

class FileIoTest : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = test::unique_temp_path("dir");
    fs::remove_all(dir_);
    fs::create_directories(dir_);
  }
  void TearDown() override { fs::remove_all(dir_); }
  fs::path dir_;
};

TEST_F(FileIoTest, ReadsWholeFile) {
  const fs::path path = dir_ / "a.bin";
  std::ofstream(path, std::ios::binary) << std::string("MThd\0\x01", 6);
  auto bytes = read_file_bytes(path);
  ASSERT_TRUE(bytes.ok());
  ASSERT_EQ(bytes->size(), 6u);
  EXPECT_EQ((*bytes)[0], 'M');
  EXPECT_EQ((*bytes)[4], 0);
  EXPECT_EQ((*bytes)[5], 1);
}

TEST_F(FileIoTest, MissingFileNamesThePath) {
  auto bytes = read_file_bytes(dir_ / "nope.mid");
  ASSERT_FALSE(bytes.ok());
  EXPECT_EQ(bytes.error().message, (dir_ / "nope.mid").string() + ": no such file");
}

TEST_F(FileIoTest, DirectoryIsRefused) {
  auto bytes = read_file_bytes(dir_);
  ASSERT_FALSE(bytes.ok());
  EXPECT_NE(bytes.error().message.find("is a directory"), std::string::npos);
}

TEST_F(FileIoTest, SizeCapIsEnforcedWithoutTrustingStat) {
  const fs::path path = dir_ / "big.bin";
  std::ofstream(path, std::ios::binary) << std::string(5000, 'x');
  auto bytes = read_file_bytes(path, 4096);
  ASSERT_FALSE(bytes.ok());
  EXPECT_NE(bytes.error().message.find("larger than"), std::string::npos);
  // Endless devices stop at the cap instead of exhausting memory.
  auto zeros = read_file_bytes("/dev/zero", 1 << 20);
  ASSERT_FALSE(zeros.ok());
}

TEST_F(FileIoTest, AtomicWriteReplacesAndLeavesNoTemporary) {
  const fs::path path = dir_ / "scene.json";
  ASSERT_TRUE(write_file_atomically(path, "first").ok());
  ASSERT_TRUE(write_file_atomically(path, "second").ok());
  auto bytes = read_file_bytes(path);
  ASSERT_TRUE(bytes.ok());
  EXPECT_EQ(std::string(bytes->begin(), bytes->end()), "second");
  int files = 0;
  for ([[maybe_unused]] const auto& entry : fs::directory_iterator(dir_)) ++files;
  EXPECT_EQ(files, 1);
}

TEST_F(FileIoTest, AtomicWriteIntoMissingFolderFailsCleanly) {
  const Status status = write_file_atomically(dir_ / "no" / "such" / "x.json", "data");
  ASSERT_FALSE(status.ok());
  EXPECT_NE(status.error().message.find("x.json"), std::string::npos);
}

}  // namespace
}  // namespace tutti
