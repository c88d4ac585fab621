// SPDX-License-Identifier: MIT
#pragma once
// The sync phase: audio_sync_system writes the frame's time (the World's ecs::FrameTime
// resource) from the clock a consumer chose, the World's FrameClock resource:
//  - `given` (or no FrameClock): the time the consumer asked Schedule::run for stays (sample(t),
//    scrubbing, seeking);
//  - `offline`: frame `frame` of a render at `fps` from `start_s`, at `tempo_factor`
//    (offline_frame_time: the picture of frame k is exactly where the rendered sound is);
//  - `live`: the AudioClock of a playing transport (its owner updates it from the device before
//    running the schedule), so the picture follows the sound.
// Every later phase sees the time written here.

#include <cstdint>

#include <tutti/audio_sync/audio_clock.hpp>
#include <tutti/ecs/schedule.hpp>
#include <tutti/ecs/world.hpp>

namespace tutti::audio_sync {

struct FrameClock {
  enum class Source : std::uint8_t { given, offline, live };
  Source source = Source::given;
  // offline
  double start_s = 0.0;
  int fps = 30;
  double tempo_factor = 1.0;
  std::int64_t frame = 0;
  // live: not owned; must outlive the runs that use it
  const AudioClock* clock = nullptr;
};

void audio_sync_system(ecs::World& world, const ecs::FrameTime& frame);

inline constexpr const char* kAudioSyncSystemName = "audio_sync";

// Adds audio_sync_system to Phase::sync under kAudioSyncSystemName.
void register_audio_sync(ecs::Schedule& schedule);

}  // namespace tutti::audio_sync
