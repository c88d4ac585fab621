// SPDX-License-Identifier: MIT
#include <tutti/runtime/transport.hpp>

#include <algorithm>
#include <cmath>
#include <string>

#include <tutti/runtime/input_bindings.hpp>

namespace tutti::runtime {
namespace {

audio_sync::AudioClockOptions clock_options(const TransportOptions& options) {
  audio_sync::AudioClockOptions clock;
  clock.sample_rate = options.sample_rate;
  clock.tempo_factor = options.tempo;
  return clock;
}

Status check_tempo(double tempo) {
  if (!(tempo >= kMinTempo && tempo <= kMaxTempo)) {
    return Error{"transport: tempo " + std::to_string(tempo) + " is outside [0.25, 2]"};
  }
  return Status::success();
}

}  // namespace

Transport::Transport(const TransportOptions& options)
    : options_(options), clock_(clock_options(options)) {}

Result<std::unique_ptr<Transport>> Transport::create(const TransportOptions& options,
                                                     OpenAudio open_audio) {
  if (!(options.end_s > options.start_s) || !std::isfinite(options.start_s) ||
      !std::isfinite(options.end_s)) {
    return Error{"transport: the end (" + std::to_string(options.end_s) +
                 " s) must come after the start (" + std::to_string(options.start_s) + " s)"};
  }
  if (Status s = check_tempo(options.tempo); !s) return s.error();
  if (options.sample_rate <= 0) return Error{"transport: the sample rate must be positive"};
  std::unique_ptr<Transport> transport(new Transport(options));
  transport->open_audio_ = std::move(open_audio);
  if (transport->open_audio_) {
    auto output = transport->open_audio_(options.tempo);
    if (!output) return output.error();
    transport->output_ = std::move(*output);
  }
  // Paused at the start: start() then pause() leaves a held, resumable clock.
  transport->clock_.start(0.0, options.start_s);
  transport->clock_.pause();
  return transport;
}

std::int64_t Transport::frame_of(double score_s) const {
  const double frames = (score_s - options_.start_s) / options_.tempo * options_.sample_rate;
  return std::max<std::int64_t>(0, static_cast<std::int64_t>(std::llround(frames)));
}

audio_sync::DevicePosition Transport::device_position(double host_s) const {
  audio_sync::DevicePosition position;
  if (output_) {
    const audio::LivePosition live = output_->position(host_s);
    position.frames_played = live.frames_played;
    position.latency_frames = live.latency_frames;
  } else if (clock_.playing()) {
    position.frames_played = static_cast<std::int64_t>(
        std::max(0.0, host_s - host_device_start_s_) * options_.sample_rate);
  }
  return position;
}

void Transport::restart_device(double host_s, double score_s) {
  host_device_start_s_ = host_s;
  if (output_) output_->play(host_s, frame_of(score_s));
}

double Transport::update(double host_s) {
  const double t = clock_.update(host_s, device_position(host_s));
  if (clock_.wrapped()) {
    restart_device(host_s, t);
    return t;
  }
  if (clock_.playing() && t >= options_.end_s) {
    pause(host_s);
    clock_.seek(host_s, options_.end_s);
    return clock_.time();
  }
  return t;
}

void Transport::play(double host_s) {
  if (clock_.playing()) return;
  if (clock_.time() >= options_.end_s) clock_.seek(host_s, options_.start_s);  // from the top
  clock_.resume(host_s);
  restart_device(host_s, clock_.time());
}

void Transport::pause(double host_s) {
  if (!clock_.playing()) return;
  clock_.pause();
  if (output_) output_->stop(host_s);
}

void Transport::toggle(double host_s) {
  if (clock_.playing()) {
    pause(host_s);
  } else {
    play(host_s);
  }
}

void Transport::seek(double host_s, double score_s) {
  const double t = std::clamp(std::isfinite(score_s) ? score_s : options_.start_s, options_.start_s,
                              options_.end_s);
  clock_.seek(host_s, t);
  if (clock_.playing()) restart_device(host_s, t);
}

void Transport::apply_loop() {
  if (const std::optional<LoopRange> range = loop()) {
    clock_.set_loop(range->from_s, range->to_s);
  } else {
    clock_.set_loop(0.0, 0.0);
  }
}

Status Transport::set_loop(double host_s, double from_s, double to_s) {
  const double from = std::clamp(from_s, options_.start_s, options_.end_s);
  const double to = std::clamp(to_s, options_.start_s, options_.end_s);
  if (!(to > from)) {
    return Error{"transport: the loop " + std::to_string(from_s) + ":" + std::to_string(to_s) +
                 " is empty within the scene"};
  }
  loop_from_s_ = from;
  loop_to_s_ = to;
  apply_loop();
  // Outside the loop: go to its start at once (else the time would run on to its end first).
  if (clock_.time() < from || clock_.time() >= to) seek(host_s, from);
  return Status::success();
}

void Transport::set_loop_start(double host_s, double score_s) {
  loop_from_s_ = std::clamp(score_s, options_.start_s, options_.end_s);
  if (loop_to_s_ && *loop_to_s_ <= *loop_from_s_) loop_to_s_.reset();
  apply_loop();
  (void)host_s;
}

void Transport::set_loop_end(double host_s, double score_s) {
  loop_to_s_ = std::clamp(score_s, options_.start_s, options_.end_s);
  if (loop_from_s_ && *loop_from_s_ >= *loop_to_s_) loop_from_s_.reset();
  apply_loop();
  // B set at the current time: the time is at the end of the loop, go round now.
  if (const std::optional<LoopRange> range = loop(); range && clock_.time() >= range->to_s) {
    seek(host_s, range->from_s);
  }
}

void Transport::clear_loop() {
  loop_from_s_.reset();
  loop_to_s_.reset();
  apply_loop();
}

std::optional<LoopRange> Transport::loop() const {
  if (!loop_from_s_ || !loop_to_s_ || !(*loop_to_s_ > *loop_from_s_)) return std::nullopt;
  return LoopRange{*loop_from_s_, *loop_to_s_};
}

Status Transport::set_tempo(double host_s, double tempo) {
  if (Status s = check_tempo(tempo); !s) return s;
  if (tempo == options_.tempo) return Status::success();
  return reopen(host_s, tempo);
}

Status Transport::reopen_sound(double host_s) { return reopen(host_s, options_.tempo); }

Status Transport::reopen(double host_s, double tempo) {
  const bool was_playing = clock_.playing();
  const double t = clock_.time();
  std::unique_ptr<audio::LiveOutput> output;
  if (open_audio_) {
    auto opened = open_audio_(tempo);
    if (!opened) return opened.error();
    output = std::move(*opened);
  }
  if (output_) output_->stop(host_s);
  output_ = std::move(output);
  options_.tempo = tempo;
  clock_ = audio_sync::AudioClock(clock_options(options_));
  clock_.start(host_s, t);
  apply_loop();
  if (was_playing) {
    restart_device(host_s, t);
  } else {
    clock_.pause();
  }
  return Status::success();
}

}  // namespace tutti::runtime
