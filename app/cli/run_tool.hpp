// SPDX-License-Identifier: MIT
#pragma once
// Runs an external tool (ffmpeg, ffprobe) from PATH with an argument vector — fork + exec, no
// shell, so any file name is safe — and returns what it printed on stdout. Errors name `what`
// and carry the tool's last line on stderr; a tool that is not installed says which package to
// install.

#include <string>
#include <vector>

#include <tutti/core/result.hpp>

namespace tutti::cli {

// args[0] is the program. Its stdout is returned (capped at 1 MiB).
Result<std::string> run_tool(const std::vector<std::string>& args, const std::string& what);

}  // namespace tutti::cli
