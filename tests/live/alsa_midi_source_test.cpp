// SPDX-License-Identifier: MIT
// The ALSA sequencer input fails cleanly: one line, no crash, when there is no sequencer (this
// build machine) or the port does not exist.
#include <tutti/live/alsa_midi_source.hpp>

#include <gtest/gtest.h>

#include <filesystem>

namespace tutti::live {
namespace {

TEST(AlsaMidiSource, NoSequencerOrNoSuchPortIsAOneLineError) {
  const bool has_sequencer = std::filesystem::exists(alsa_sequencer_device());
  for (const char* port : {"", "auto", "20:0", "No Such Keyboard"}) {
    auto source = AlsaMidiSource::open(port);
    if (has_sequencer && (std::string(port).empty() || std::string(port) == "auto")) {
      EXPECT_TRUE(source.ok()) << source.error().message;
      continue;
    }
    if (has_sequencer && std::string(port) == "20:0") continue;  // a device may be there
    ASSERT_FALSE(source.ok()) << port;
    const std::string& message = source.error().message;
    EXPECT_EQ(message.find('\n'), std::string::npos) << message;
    EXPECT_EQ(message.rfind("ALSA sequencer: ", 0), 0u) << message;
    if (!has_sequencer) {
      EXPECT_NE(message.find("/dev/snd/seq"), std::string::npos) << message;
    } else {
      EXPECT_NE(message.find("No Such Keyboard"), std::string::npos) << message;
    }
  }
}

}  // namespace
}  // namespace tutti::live
