// SPDX-License-Identifier: MIT
#pragma once
// Where the third-party inputs are. Tests that need them call TUTTI_REQUIRE_TESTDATA() first,
// which skips with a clear message when ../shared/testdata is not beside the checkout.

#include <gtest/gtest.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <set>
#include <string>

namespace tutti::test {

inline std::filesystem::path testdata_dir() { return TUTTI_TESTDATA_DIR; }
inline std::filesystem::path source_dir() { return TUTTI_SOURCE_DIR; }
inline std::filesystem::path testdata(const std::string& relative) {
  return testdata_dir() / relative;
}

// A path in the temporary folder that no other test process uses at the same time (ctest runs
// tests in parallel, and the default and asan builds may run at once).
inline std::filesystem::path unique_temp_path(const std::string& name) {
  const auto* info = ::testing::UnitTest::GetInstance()->current_test_info();
  std::string test = info ? std::string(info->test_suite_name()) + "." + info->name() : "none";
  return std::filesystem::temp_directory_path() /
         ("tutti-" + std::to_string(::getpid()) + "-" + test + "-" + name);
}

// The third-party files tutti must refuse (tests/data/broken_files.txt), those whose path
// starts with `prefix`. Lines: "relative/path  # reason"; '#' lines are comments.
inline std::set<std::string> broken_testdata_files(const std::string& prefix = "") {
  std::set<std::string> files;
  std::ifstream in(source_dir() / "tests" / "data" / "broken_files.txt");
  for (std::string line; std::getline(in, line);) {
    line = line.substr(0, line.find('#'));
    line.erase(line.find_last_not_of(" \t\r") + 1);
    if (!line.empty() && line.rfind(prefix, 0) == 0) files.insert(line);
  }
  return files;
}

}  // namespace tutti::test

#define TUTTI_REQUIRE_TESTDATA()                                                             \
  do {                                                                                       \
    if (!std::filesystem::is_directory(::tutti::test::testdata_dir())) {                     \
      GTEST_SKIP() << "third-party test data not found at " << ::tutti::test::testdata_dir() \
                   << " (expected ../shared/testdata)";                                      \
    }                                                                                        \
  } while (false)
