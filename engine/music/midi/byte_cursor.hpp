// SPDX-License-Identifier: MIT
#pragma once
// A bounds-checked, forward-only view of a byte range inside a file. Every read either succeeds
// or reports failure without moving, so a parser can never step past the bytes it was given, and
// `offset()` is always the absolute file position to quote in an error message.

#include <cstddef>
#include <cstdint>
#include <optional>
#include <span>

namespace tutti::music::midi_detail {

// Result of reading a MIDI variable-length quantity (7 bits per byte, high bit = "more").
struct VarLen {
  enum class Status : std::uint8_t { ok, truncated, too_long };
  Status status = Status::ok;
  std::uint32_t value = 0;
};

class ByteCursor {
 public:
  // The largest variable-length quantity the SMF specification allows: 4 bytes, 0x0FFFFFFF.
  static constexpr int kMaxVarLenBytes = 4;

  ByteCursor(std::span<const std::uint8_t> bytes, std::size_t file_offset_of_first_byte)
      : bytes_(bytes), base_(file_offset_of_first_byte) {}

  std::size_t offset() const { return base_ + position_; }
  std::size_t remaining() const { return bytes_.size() - position_; }
  bool at_end() const { return position_ == bytes_.size(); }

  std::optional<std::uint8_t> peek() const {
    if (at_end()) return std::nullopt;
    return bytes_[position_];
  }

  std::optional<std::uint8_t> read_u8() {
    if (at_end()) return std::nullopt;
    return bytes_[position_++];
  }

  // n bytes as a view into the input (no copy), or nullopt when fewer than n are left.
  std::optional<std::span<const std::uint8_t>> read_bytes(std::size_t n) {
    if (n > remaining()) return std::nullopt;
    auto view = bytes_.subspan(position_, n);
    position_ += n;
    return view;
  }

  std::optional<std::uint32_t> read_be16() { return read_big_endian(2); }
  std::optional<std::uint32_t> read_be32() { return read_big_endian(4); }

  std::optional<std::uint32_t> read_le32() {
    if (remaining() < 4) return std::nullopt;
    std::uint32_t value = 0;
    for (int i = 3; i >= 0; --i)
      value = (value << 8) | bytes_[position_ + static_cast<std::size_t>(i)];
    position_ += 4;
    return value;
  }

  // On failure the cursor does not move, so offset() still points at the quantity's first byte.
  VarLen read_varlen() {
    VarLen result;
    std::size_t at = position_;
    for (int count = 0; count < kMaxVarLenBytes; ++count) {
      if (at == bytes_.size()) return {VarLen::Status::truncated, 0};
      const std::uint8_t byte = bytes_[at++];
      result.value = (result.value << 7) | (byte & 0x7Fu);
      if ((byte & 0x80u) == 0) {
        position_ = at;
        return result;
      }
    }
    return {VarLen::Status::too_long, 0};
  }

 private:
  std::optional<std::uint32_t> read_big_endian(std::size_t n) {
    if (remaining() < n) return std::nullopt;
    std::uint32_t value = 0;
    for (std::size_t i = 0; i < n; ++i) value = (value << 8) | bytes_[position_ + i];
    position_ += n;
    return value;
  }

  std::span<const std::uint8_t> bytes_;
  std::size_t base_ = 0;
  std::size_t position_ = 0;
};

}  // namespace tutti::music::midi_detail
