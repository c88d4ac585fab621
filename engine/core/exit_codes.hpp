// SPDX-License-Identifier: MIT
#pragma once
// The exit codes of every tutti program (README "Exit codes"): the command line, the editor,
// the examples; here, under the programs, so that any of them can use them:
//   0  done
//   1  tutti's own fault (an internal error; please report it)
//   2  bad input or usage: the message names the file or option and what is wrong
//   3  the machine lacks something: a Vulkan device, ffmpeg, a sound font, a display

#include <ostream>
#include <string>

#include <tutti/core/result.hpp>

namespace tutti {

inline constexpr int kExitOk = 0;
inline constexpr int kExitInternal = 1;
inline constexpr int kExitBadInput = 2;
inline constexpr int kExitEnvironment = 3;

// The exit code for an error, from its ErrorCode.
inline int exit_code_of(const Error& error) {
  switch (error.code) {
    case ErrorCode::environment: return kExitEnvironment;
    case ErrorCode::internal: return kExitInternal;
    case ErrorCode::bad_input: break;
  }
  return kExitBadInput;
}

// A command's failure: "error: <message>" on `err`, and the exit code of the error's kind
// (a plain message is bad input).
struct Fail {
  std::ostream& err;
  int operator()(const Error& error) const {
    err << "error: " << error.message << "\n";
    return exit_code_of(error);
  }
  int operator()(const std::string& message) const { return (*this)(Error{message}); }
};

}  // namespace tutti
