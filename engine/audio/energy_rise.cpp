// SPDX-License-Identifier: MIT
#include <tutti/audio/energy_rise.hpp>

#include <algorithm>
#include <cmath>
#include <vector>

namespace tutti::audio {

double steepest_energy_rise_s(const AudioBuffer& audio, double from_s, double to_s,
                              double fallback_s, const EnergyRiseOptions& o) {
  const std::int64_t frames = audio.frames();
  const int rate = audio.sample_rate;
  const int channels = std::max(audio.channels, 1);
  if (frames <= 0 || rate <= 0) return fallback_s;
  const auto window = std::max<std::int64_t>(1, std::llround(o.window_s * rate));
  const auto hop = std::max<std::int64_t>(1, std::llround(o.hop_s * rate));
  const auto first = std::max<std::int64_t>(window, std::llround(from_s * rate));
  const auto last = std::min<std::int64_t>(frames, std::llround(to_s * rate));
  if (last <= first + hop) return fallback_s;
  // Prefix sums of the mixed-down square over the span and its window.
  const std::int64_t begin = first - window;
  std::vector<double> prefix(static_cast<std::size_t>(last - begin + 1), 0.0);
  for (std::int64_t f = begin; f < last; ++f) {
    double mono = 0.0;
    for (int c = 0; c < channels; ++c) {
      mono += audio.samples[static_cast<std::size_t>(f * channels + c)];
    }
    mono /= channels * 32768.0;
    prefix[static_cast<std::size_t>(f - begin + 1)] =
        prefix[static_cast<std::size_t>(f - begin)] + mono * mono;
  }
  const double floor = std::pow(10.0, o.floor_dbfs / 10.0);
  const auto level_db = [&](std::int64_t end) {
    const double sum = prefix[static_cast<std::size_t>(end - begin)] -
                       prefix[static_cast<std::size_t>(end - window - begin)];
    return 10.0 * std::log10(sum / static_cast<double>(window) + floor);
  };
  double best_rise = 0.0;
  double best_s = fallback_s;
  double previous = level_db(first);
  for (std::int64_t end = first + hop; end <= last; end += hop) {
    const double now = level_db(end);
    if (now - previous > best_rise) {
      best_rise = now - previous;
      // A sound raises the level fastest as it enters the window: halfway through the step.
      best_s = (static_cast<double>(end) - 0.5 * static_cast<double>(hop)) / rate;
    }
    previous = now;
  }
  return best_s;
}

}  // namespace tutti::audio
