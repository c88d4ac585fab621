// SPDX-License-Identifier: MIT
#pragma once
// 16-bit PCM WAV (RIFF) files: written atomically (a crash mid-write leaves the previous file),
// read back with every header field and chunk size checked.

#include <cstdint>
#include <filesystem>
#include <span>
#include <string>

#include <tutti/audio/offline_synth.hpp>
#include <tutti/core/result.hpp>

namespace tutti::audio {

Status write_wav(const std::filesystem::path& path, const AudioBuffer& audio);

// The RIFF bytes of `audio` (what write_wav writes).
std::string wav_bytes(const AudioBuffer& audio);

// Errors name the file and the problem ("x.wav: not a RIFF/WAVE file", "x.wav: data chunk
// runs past the end of the file", "x.wav: 24-bit samples (only 16-bit PCM is read)").
Result<AudioBuffer> read_wav(const std::filesystem::path& path);
Result<AudioBuffer> parse_wav(std::span<const std::uint8_t> bytes, const std::string& name);

}  // namespace tutti::audio
