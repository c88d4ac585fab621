// SPDX-License-Identifier: MIT
#include <tutti/audio_sync/audio_sync_system.hpp>

namespace tutti::audio_sync {

void audio_sync_system(ecs::World& world, const ecs::FrameTime& frame) {
  const FrameClock* clock = world.resource<FrameClock>();
  if (clock == nullptr) return;
  switch (clock->source) {
    case FrameClock::Source::given:
      return;
    case FrameClock::Source::offline:
      world.set_resource<ecs::FrameTime>(
          {offline_frame_time(clock->start_s, clock->fps, clock->frame, clock->tempo_factor),
           clock->fps > 0 ? clock->tempo_factor / clock->fps : 0.0});
      return;
    case FrameClock::Source::live:
      if (clock->clock != nullptr) world.set_resource<ecs::FrameTime>({clock->clock->time(), frame.dt_s});
      return;
  }
}

void register_audio_sync(ecs::Schedule& schedule) {
  schedule.add(ecs::Phase::sync, kAudioSyncSystemName, audio_sync_system,
               ecs::access(ecs::Reads<FrameClock, AudioClock>{}, ecs::Writes<ecs::FrameTime>{}));
}

}  // namespace tutti::audio_sync
