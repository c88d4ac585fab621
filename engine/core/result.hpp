// SPDX-License-Identifier: MIT
#pragma once
// Errors as values (vk-bootstrap / ACL style): a reader never throws across a module boundary.
// An Error's message is a single line that already names the file and the reason, e.g.
// "song.mid: track 2 at byte 812: delta time longer than 4 bytes". The CLI prints it verbatim
// after "error: ". Its code says what kind of failure it is.

#include <string>
#include <utility>
#include <variant>

namespace tutti {

// What kind of failure an Error is, for programs and bindings that act on it (the C API returns
// it; a command line turns it into an exit code).
enum class ErrorCode : unsigned char {
  bad_input = 2,    // a file or value the caller gave is wrong (the default)
  environment = 3,  // the machine lacks something: a Vulkan device, ffmpeg, a sound font, a display
  internal = 1,     // tutti's own fault
};

struct Error {
  std::string message;
  ErrorCode code = ErrorCode::bad_input;
};

template <typename T>
class [[nodiscard]] Result {
 public:
  Result(T value) : state_(std::move(value)) {}      // NOLINT: implicit by design
  Result(Error error) : state_(std::move(error)) {}  // NOLINT: implicit by design

  bool ok() const { return std::holds_alternative<T>(state_); }
  explicit operator bool() const { return ok(); }

  // Precondition: ok(). Calling these on an error is a programming bug.
  T& value() & { return std::get<T>(state_); }
  const T& value() const& { return std::get<T>(state_); }
  T&& value() && { return std::get<T>(std::move(state_)); }
  T* operator->() { return &value(); }
  const T* operator->() const { return &value(); }
  T& operator*() & { return value(); }
  const T& operator*() const& { return value(); }

  // Precondition: !ok().
  const Error& error() const { return std::get<Error>(state_); }

 private:
  std::variant<T, Error> state_;
};

// For operations that produce nothing but may fail.
class [[nodiscard]] Status {
 public:
  Status() = default;
  Status(Error error) : error_(std::move(error)), ok_(false) {}  // NOLINT: implicit by design
  static Status success() { return {}; }

  bool ok() const { return ok_; }
  explicit operator bool() const { return ok_; }
  const Error& error() const { return error_; }

 private:
  Error error_;
  bool ok_ = true;
};

}  // namespace tutti
