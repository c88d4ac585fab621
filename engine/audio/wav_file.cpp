// SPDX-License-Identifier: MIT
#include <tutti/audio/wav_file.hpp>

#include <cstring>

#include <tutti/core/file_io.hpp>

namespace tutti::audio {
namespace {

void put_u32(std::string& out, std::uint32_t v) {
  for (int i = 0; i < 4; ++i) out.push_back(static_cast<char>((v >> (8 * i)) & 0xFF));
}
void put_u16(std::string& out, std::uint16_t v) {
  out.push_back(static_cast<char>(v & 0xFF));
  out.push_back(static_cast<char>(v >> 8));
}
std::uint32_t get_u32(std::span<const std::uint8_t> b, std::size_t at) {
  return static_cast<std::uint32_t>(b[at]) | (static_cast<std::uint32_t>(b[at + 1]) << 8) |
         (static_cast<std::uint32_t>(b[at + 2]) << 16) |
         (static_cast<std::uint32_t>(b[at + 3]) << 24);
}
std::uint16_t get_u16(std::span<const std::uint8_t> b, std::size_t at) {
  return static_cast<std::uint16_t>(b[at] | (b[at + 1] << 8));
}
bool tag_is(std::span<const std::uint8_t> b, std::size_t at, const char* tag) {
  return std::memcmp(b.data() + at, tag, 4) == 0;
}

}  // namespace

std::string wav_bytes(const AudioBuffer& audio) {
  const auto data_bytes = static_cast<std::uint32_t>(audio.samples.size() * 2);
  const auto channels = static_cast<std::uint16_t>(audio.channels);
  const auto rate = static_cast<std::uint32_t>(audio.sample_rate);
  std::string out;
  out.reserve(44 + data_bytes);
  out += "RIFF";
  put_u32(out, 36 + data_bytes);
  out += "WAVEfmt ";
  put_u32(out, 16);
  put_u16(out, 1);  // PCM
  put_u16(out, channels);
  put_u32(out, rate);
  put_u32(out, rate * channels * 2);
  put_u16(out, static_cast<std::uint16_t>(channels * 2));
  put_u16(out, 16);
  out += "data";
  put_u32(out, data_bytes);
  for (std::int16_t s : audio.samples) put_u16(out, static_cast<std::uint16_t>(s));
  return out;
}

Status write_wav(const std::filesystem::path& path, const AudioBuffer& audio) {
  if (audio.samples.size() * 2 > 0xFFFFFF00u) {
    return Error{path.string() + ": too much audio for one WAV file (4 GiB)"};
  }
  return write_file_atomically(path, wav_bytes(audio));
}

Result<AudioBuffer> parse_wav(std::span<const std::uint8_t> b, const std::string& name) {
  if (b.size() < 12 || !tag_is(b, 0, "RIFF") || !tag_is(b, 8, "WAVE")) {
    return Error{name + ": not a RIFF/WAVE file"};
  }
  AudioBuffer out;
  bool have_format = false;
  std::size_t at = 12;
  while (at + 8 <= b.size()) {
    const std::uint32_t size = get_u32(b, at + 4);
    const std::size_t body = at + 8;
    if (size > b.size() - body) {
      return Error{name + ": " + std::string(reinterpret_cast<const char*>(b.data() + at), 4) +
                   " chunk runs past the end of the file"};
    }
    if (tag_is(b, at, "fmt ")) {
      if (size < 16) return Error{name + ": fmt chunk shorter than 16 bytes"};
      const std::uint16_t format = get_u16(b, body);
      const std::uint16_t channels = get_u16(b, body + 2);
      const std::uint32_t rate = get_u32(b, body + 4);
      const std::uint16_t bits = get_u16(b, body + 14);
      if (format != 1)
        return Error{name + ": format " + std::to_string(format) + " (only PCM is read)"};
      if (bits != 16) {
        return Error{name + ": " + std::to_string(bits) + "-bit samples (only 16-bit PCM is read)"};
      }
      if (channels < 1 || channels > 8) {
        return Error{name + ": " + std::to_string(channels) + " channels"};
      }
      if (rate < 1000 || rate > 384000)
        return Error{name + ": sample rate " + std::to_string(rate)};
      out.channels = channels;
      out.sample_rate = static_cast<int>(rate);
      have_format = true;
    } else if (tag_is(b, at, "data")) {
      if (!have_format) return Error{name + ": data chunk before the fmt chunk"};
      const std::size_t frame_bytes = static_cast<std::size_t>(out.channels) * 2;
      if (size % frame_bytes != 0) return Error{name + ": data chunk is not whole frames"};
      out.samples.resize(size / 2);
      for (std::size_t i = 0; i < out.samples.size(); ++i) {
        out.samples[i] = static_cast<std::int16_t>(get_u16(b, body + 2 * i));
      }
      return out;
    }
    at = body + size + (size & 1u);  // chunks are padded to even sizes
  }
  return Error{name + ": no data chunk"};
}

Result<AudioBuffer> read_wav(const std::filesystem::path& path) {
  auto bytes = read_file_bytes(path, std::size_t{2} << 30);
  if (!bytes) return bytes.error();
  return parse_wav(*bytes, path.string());
}

}  // namespace tutti::audio
