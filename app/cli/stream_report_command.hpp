// SPDX-License-Identifier: MIT
#pragma once
// `tutti-stream-report FILE...`: the streaming fingering planner against the exact one
// (fingering_planner/streaming_report.hpp), one Markdown table row per file and lookahead, then
// the totals per lookahead. The README's "Live input" table is its output.

#include <filesystem>
#include <iosfwd>
#include <string>
#include <vector>

namespace tutti::cli {

struct StreamReportOptions {
  std::vector<std::filesystem::path> inputs;
  std::vector<int> lookaheads{0, 3, 6};
  std::string weights = "default";  // a preset of content/piano/fingering/
};

int run_stream_report(const StreamReportOptions& options, std::ostream& out, std::ostream& err);

}  // namespace tutti::cli
