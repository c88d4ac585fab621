// SPDX-License-Identifier: MIT
// The `tutti` command line as a user meets it: a mistyped command or option names the closest
// one, and the exit code says whose problem it is — 2 bad input, 3 a missing environment (see
// render_command_test and play_command_test), 1 tutti's own fault.
#include <tutti/cli/command.hpp>
#include <tutti/core/exit_codes.hpp>
#include <tutti/cli/fingering_command.hpp>
#include <tutti/cli/info_command.hpp>
#include <tutti/cli/render_command.hpp>
#include <tutti/cli/scene_command.hpp>

#include <gtest/gtest.h>

#include <sstream>
#include <stdexcept>
#include <vector>

namespace tutti::cli {
namespace {

struct Outcome {
  int code = -1;
  std::string out;
  std::string err;
};

Outcome run(const Commands& commands, std::vector<const char*> argv) {
  std::ostringstream out;
  std::ostringstream err;
  Outcome r;
  r.code = commands.run(static_cast<int>(argv.size()), argv.data(), "tutti", "tutti 0", out, err);
  r.out = out.str();
  r.err = err.str();
  return r;
}

// Some of tutti's own commands (commands.cpp, in the executable, registers them all).
Commands tutti_commands() {
  Commands commands;
  register_info_command(commands);
  register_fingering_command(commands);
  register_scene_command(commands);
  register_render_command(commands);
  return commands;
}

TEST(ExitCodes, AMistypedCommandNamesTheClosestOne) {
  const Commands commands = tutti_commands();
  Outcome r = run(commands, {"tutti", "rendr", "scene.json"});
  EXPECT_EQ(r.code, kExitBadInput);
  EXPECT_EQ(r.err, "error: \"rendr\" is not a command (did you mean \"render\"?) (see tutti --help)\n");
  r = run(commands, {"tutti", "fingring", "x.mid"});
  EXPECT_EQ(r.err,
            "error: \"fingring\" is not a command (did you mean \"fingering\"?) (see tutti --help)\n");
  r = run(commands, {"tutti", "xyzzy"});
  EXPECT_EQ(r.code, kExitBadInput);
  EXPECT_EQ(r.err, "error: \"xyzzy\" is not a command (see tutti --help)\n");
}

TEST(ExitCodes, AMistypedOptionNamesTheClosestOne) {
  const Commands commands = tutti_commands();
  const Outcome r = run(commands, {"tutti", "render", "scene.json", "-o", "a.mp4", "--frams", "0:3"});
  EXPECT_EQ(r.code, kExitBadInput);
  EXPECT_NE(r.err.find("(did you mean \"--frames\"?)"), std::string::npos) << r.err;
  EXPECT_EQ(r.err.find('\n'), r.err.size() - 1) << "one line: " << r.err;
}

TEST(ExitCodes, AnExceptionIsAnInternalErrorNotACrash) {
  Commands commands;
  commands.add("boom", "throws").on_run([](std::ostream&, std::ostream&) -> int {
    throw std::runtime_error("vector::at out of range");
  });
  const Outcome r = run(commands, {"tutti", "boom"});
  EXPECT_EQ(r.code, kExitInternal);
  EXPECT_EQ(r.err,
            "error: internal error in tutti boom: vector::at out of range (please report it)\n");
}

TEST(ExitCodes, EachKindOfErrorHasItsCode) {
  EXPECT_EQ(exit_code_of(Error{"x.mid: truncated"}), 2);
  EXPECT_EQ(exit_code_of(Error{"no Vulkan device", ErrorCode::environment}), 3);
  EXPECT_EQ(exit_code_of(Error{"bug", ErrorCode::internal}), 1);
}

}  // namespace
}  // namespace tutti::cli
