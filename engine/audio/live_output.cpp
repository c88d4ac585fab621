// SPDX-License-Identifier: MIT
#include <tutti/audio/live_output.hpp>

#include <algorithm>
#include <cmath>
#include <vector>

#include <tutti/audio/fluid_synth_util.hpp>

namespace tutti::audio {

struct LiveOutput::Impl {
  std::unique_ptr<fluid_settings_t, SettingsDeleter> settings;
  std::unique_ptr<fluid_synth_t, SynthDeleter> synth;
  std::unique_ptr<fluid_audio_driver_t, AudioDriverDeleter> driver;  // null when simulated
};

namespace {

int driver_callback(void* data, int len, int /*nfx*/, float* /*fx*/[], int nout, float* out[]) {
  if (nout < 2 || out == nullptr) return FLUID_FAILED;
  static_cast<LiveOutput*>(data)->render(len, out[0], out[1]);
  return FLUID_OK;
}

}  // namespace

Result<std::unique_ptr<LiveOutput>> LiveOutput::open(const SynthTimeline& timeline,
                                                     const LiveOutputOptions& options) {
  quiet_fluid_log();
  if (options.period_frames < 64 || options.period_frames > 8192 || options.periods < 2 ||
      options.periods > 16) {
    return Error{"audio: live output needs 64..8192 frames per period and 2..16 periods"};
  }
  std::unique_ptr<LiveOutput> out(new LiveOutput());
  out->timeline_ = timeline;
  out->options_ = options;
  out->impl_ = std::make_unique<Impl>();
  Impl& impl = *out->impl_;
  impl.settings.reset(new_fluid_settings());
  if (!impl.settings) return Error{"audio: FluidSynth settings could not be created"};
  fluid_settings_t* s = impl.settings.get();
  fluid_settings_setnum(s, "synth.sample-rate", timeline.sample_rate);
  fluid_settings_setint(s, "synth.midi-channels", timeline.channel_count);
  fluid_settings_setint(s, "synth.cpu-cores", 1);
  fluid_settings_setint(s, "synth.polyphony", 512);
  fluid_settings_setnum(s, "synth.gain", options.gain);
  fluid_settings_setint(s, "audio.period-size", options.period_frames);
  fluid_settings_setint(s, "audio.periods", options.periods);
  impl.synth.reset(new_fluid_synth(s));
  if (!impl.synth) return Error{"audio: FluidSynth could not start: " + last_fluid_error()};
  if (fluid_synth_sfload(impl.synth.get(), options.sound_font.c_str(), 1) == FLUID_FAILED) {
    return Error{options.sound_font.string() + ": not a sound font FluidSynth can load (" +
                 last_fluid_error() + ")"};
  }
  if (options.driver != "simulated") {
    if (!options.driver.empty()) fluid_settings_setstr(s, "audio.driver", options.driver.c_str());
    char* name = nullptr;
    if (fluid_settings_dupstr(s, "audio.driver", &name) == FLUID_OK && name != nullptr) {
      out->device_ = name;
      fluid_free(name);
    }
    impl.driver.reset(new_fluid_audio_driver2(s, driver_callback, out.get()));
    if (!impl.driver && !options.allow_simulated) {
      return Error{"audio: no audio device through FluidSynth's \"" + out->device_ + "\" driver (" +
                   last_fluid_error() + ")"};
    }
  }
  if (!impl.driver) {
    out->simulated_ = true;
    out->device_ = "simulated";
  }
  return out;
}

LiveOutput::~LiveOutput() {
  // The driver's thread calls render(): stop it before anything it uses goes.
  if (impl_) impl_->driver.reset();
}

void LiveOutput::play(double host_s, std::int64_t frame) {
  playing_.store(false);
  handed_at_play_.store(handed_.load());
  started_host_s_.store(host_s);
  held_frames_.store(0);
  seek_to_.store(std::max<std::int64_t>(0, frame) / kSynthBlockFrames * kSynthBlockFrames);
  playing_.store(true);
}

void LiveOutput::stop(double host_s) {
  held_frames_.store(position(host_s).frames_played);
  playing_.store(false);
}

LivePosition LiveOutput::position(double host_s) const {
  LivePosition p;
  p.latency_frames = static_cast<std::int64_t>(options_.period_frames) * options_.periods;
  if (!playing_.load()) {
    p.frames_played = held_frames_.load();
    return p;
  }
  if (simulated_) {
    // Whole periods at the nominal rate since play(), as a device reports them.
    const double frames = std::max(0.0, host_s - started_host_s_.load()) * timeline_.sample_rate;
    const auto periods = static_cast<std::int64_t>(std::floor(frames / options_.period_frames));
    p.frames_played = periods * options_.period_frames;
  } else {
    p.frames_played = handed_.load() - handed_at_play_.load();
  }
  return p;
}

void LiveOutput::apply_seek(std::int64_t frame) {
  fluid_synth_t* synth = impl_->synth.get();
  fluid_synth_all_sounds_off(synth, -1);
  // Programs and controllers as they stand at `frame`; notes start from there.
  next_ = 0;
  while (next_ < timeline_.events.size() && timeline_.events[next_].frame < frame) {
    const SynthEvent& e = timeline_.events[next_++];
    if (e.kind == SynthEventKind::program || e.kind == SynthEventKind::control) {
      send_event(synth, e);
    }
  }
  at_ = frame;
}

void LiveOutput::render(int frames, float* left, float* right) {
  std::fill(left, left + frames, 0.0f);
  std::fill(right, right + frames, 0.0f);
  if (const std::int64_t seek = seek_to_.exchange(-1); seek >= 0) apply_seek(seek);
  if (!playing_.load()) return;
  fluid_synth_t* synth = impl_->synth.get();
  int done = 0;
  while (done < frames) {
    if (at_ % kSynthBlockFrames == 0) {
      while (next_ < timeline_.events.size() && timeline_.events[next_].frame <= at_) {
        send_event(synth, timeline_.events[next_++]);
      }
    }
    const int chunk = static_cast<int>(
        std::min<std::int64_t>(frames - done, kSynthBlockFrames - at_ % kSynthBlockFrames));
    float* dry[2] = {left + done, right + done};
    float* fx[4] = {left + done, right + done, left + done, right + done};  // effects mixed in
    fluid_synth_process(synth, chunk, 4, fx, 2, dry);
    done += chunk;
    at_ += chunk;
  }
  handed_.fetch_add(frames);
}

}  // namespace tutti::audio
