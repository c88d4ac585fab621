// SPDX-License-Identifier: MIT
// WAV writing and reading (audio/wav_file.hpp): round trip, and hostile or truncated files.
#include <tutti/audio/wav_file.hpp>

#include <gtest/gtest.h>
#include <unistd.h>

#include <filesystem>
#include <string>
#include <vector>

namespace tutti::audio {
namespace {

AudioBuffer ramp() {
  AudioBuffer audio;
  audio.sample_rate = 48000;
  audio.channels = 2;
  for (int i = 0; i < 1000; ++i) {
    audio.samples.push_back(static_cast<std::int16_t>(i * 37 - 18000));
    audio.samples.push_back(static_cast<std::int16_t>(-i * 29 + 12000));
  }
  return audio;
}

std::vector<std::uint8_t> bytes_of(const std::string& s) { return {s.begin(), s.end()}; }

TEST(WavFile, RoundTripKeepsEverySample) {
  const auto path =
      std::filesystem::temp_directory_path() / ("tutti-wav-" + std::to_string(getpid()) + ".wav");
  const AudioBuffer audio = ramp();
  ASSERT_TRUE(write_wav(path, audio));
  EXPECT_EQ(std::filesystem::file_size(path), 44u + audio.samples.size() * 2);
  auto back = read_wav(path);
  std::filesystem::remove(path);
  ASSERT_TRUE(back) << back.error().message;
  EXPECT_EQ(back->sample_rate, 48000);
  EXPECT_EQ(back->channels, 2);
  EXPECT_EQ(back->samples, audio.samples);
}

TEST(WavFile, HostileFilesAreOneLineErrors) {
  const std::string good = wav_bytes(ramp());
  struct Case {
    std::string bytes;
    std::string expected;
  };
  std::string truncated = good.substr(0, good.size() - 10);
  std::string float_format = good;
  float_format[20] = 3;  // IEEE float
  std::string wide = good;
  wide[34] = 24;
  std::string huge_chunk = good;
  huge_chunk[40] = '\xff';
  huge_chunk[41] = '\xff';
  huge_chunk[42] = '\xff';
  huge_chunk[43] = '\x7f';
  std::string no_channels = good;
  no_channels[22] = 0;
  const Case cases[] = {
      {"", "x.wav: not a RIFF/WAVE file"},
      {"RIFF\x10\0\0\0WAVX", "x.wav: not a RIFF/WAVE file"},
      {truncated, "x.wav: data chunk runs past the end of the file"},
      {float_format, "x.wav: format 3 (only PCM is read)"},
      {wide, "x.wav: 24-bit samples (only 16-bit PCM is read)"},
      {huge_chunk, "x.wav: data chunk runs past the end of the file"},
      {no_channels, "x.wav: 0 channels"},
      {good.substr(0, 30), "x.wav: fmt  chunk runs past the end of the file"},
      {good.substr(0, 36), "x.wav: no data chunk"},
      {good.substr(0, 12), "x.wav: no data chunk"},
  };
  for (const Case& c : cases) {
    auto parsed = parse_wav(bytes_of(c.bytes), "x.wav");
    ASSERT_FALSE(parsed) << c.expected;
    EXPECT_EQ(parsed.error().message, c.expected);
  }
  EXPECT_FALSE(read_wav("/nonexistent/tutti.wav"));
}

}  // namespace
}  // namespace tutti::audio
