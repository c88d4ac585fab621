#pragma once
// `tutti info FILE [--json]`: what is in a score file.

#include <filesystem>
#include <iosfwd>

namespace tutti::app {

struct InfoOptions {
  std::filesystem::path file;
  bool json = false;
};

// Prints the report to `out`, or one "error: ..." line to `err`. Returns the exit code.
int run_info(const InfoOptions& options, std::ostream& out, std::ostream& err);

}  // namespace tutti::app
