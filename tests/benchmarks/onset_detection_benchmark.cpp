// SPDX-License-Identifier: MIT
// detect_onsets on 10 s of 48 kHz stereo: four voices changing note every 0.4 s with a 6 Hz
// tremolo, like the quartet's texture (no sound font needed).
#include <benchmark/benchmark.h>

#include <cmath>
#include <numbers>

#include <tutti/audio/onset_detection.hpp>

namespace {

tutti::audio::AudioBuffer texture(double seconds) {
  constexpr int kRate = 48000;
  tutti::audio::AudioBuffer audio;
  const auto frames = static_cast<std::size_t>(seconds * kRate);
  audio.samples.resize(frames * 2);
  const double roots[] = {116.5, 174.6, 233.1, 293.7};
  for (std::size_t i = 0; i < frames; ++i) {
    const double t = static_cast<double>(i) / kRate;
    const int step = static_cast<int>(t / 0.4);
    double v = 0.0;
    for (int voice = 0; voice < 4; ++voice) {
      const double hz = roots[voice] * std::pow(2.0, ((step + voice) % 5) / 12.0);
      const double tremolo = 1.0 + 0.1 * std::sin(2.0 * std::numbers::pi * 6.0 * t);
      for (int h = 1; h <= 4; ++h)
        v += 0.04 * tremolo * std::sin(2.0 * std::numbers::pi * hz * h * t) / h;
    }
    const auto s = static_cast<std::int16_t>(std::lround(v * 32767.0));
    audio.samples[2 * i] = s;
    audio.samples[2 * i + 1] = s;
  }
  return audio;
}

void BM_DetectOnsets10s(benchmark::State& state) {
  const tutti::audio::AudioBuffer audio = texture(10.0);
  std::size_t found = 0;
  for (auto _ : state) {
    const auto onsets = tutti::audio::detect_onsets(audio);
    found = onsets.size();
    benchmark::DoNotOptimize(onsets.data());
  }
  state.counters["onsets"] = static_cast<double>(found);
  state.counters["x_realtime"] = benchmark::Counter(10.0 * static_cast<double>(state.iterations()),
                                                    benchmark::Counter::kIsRate);
}
BENCHMARK(BM_DetectOnsets10s)->Unit(benchmark::kMillisecond);

}  // namespace
