// SPDX-License-Identifier: MIT
#include <tutti/audio/onset_detection.hpp>

#include <kiss_fftr.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <memory>
#include <numbers>

namespace tutti::audio {
namespace {

struct FftrDeleter {
  void operator()(kiss_fftr_state* cfg) const { kiss_fftr_free(cfg); }
};

// Mono, full scale = 1.
std::vector<float> mono_of(const AudioBuffer& audio) {
  const auto channels = static_cast<std::size_t>(std::max(audio.channels, 1));
  const std::size_t frames = audio.samples.size() / channels;
  std::vector<float> mono(frames, 0.0f);
  const float scale = 1.0f / (32768.0f * static_cast<float>(channels));
  for (std::size_t i = 0; i < frames; ++i) {
    float sum = 0.0f;
    for (std::size_t c = 0; c < channels; ++c) sum += audio.samples[i * channels + c];
    mono[i] = sum * scale;
  }
  return mono;
}

// Triangular bands, `bands_per_octave` per octave from 30 Hz to 16 kHz, over FFT bins; bands
// that would cover the same bins as their neighbour (low frequencies) are merged away.
struct Band {
  std::size_t first = 0, peak = 0, last = 0;  // bins [first, last], weight 1 at peak
};

std::vector<Band> make_bands(std::size_t n, int sample_rate, int bands_per_octave) {
  std::vector<std::size_t> centres;
  const double bin_hz = static_cast<double>(sample_rate) / static_cast<double>(n);
  for (double f = 30.0; f < std::min(16000.0, 0.5 * sample_rate);
       f *= std::pow(2.0, 1.0 / bands_per_octave)) {
    const auto bin = static_cast<std::size_t>(std::lround(f / bin_hz));
    if (bin >= 1 && bin < n / 2 && (centres.empty() || bin > centres.back()))
      centres.push_back(bin);
  }
  std::vector<Band> bands;
  for (std::size_t i = 1; i + 1 < centres.size(); ++i) {
    bands.push_back({centres[i - 1], centres[i], centres[i + 1]});
  }
  return bands;
}

// The analysis window, oldest sample first: a long half-Hann rise over the past (frequency
// resolution), then a 2 ms fall at the newest end, so a new sound is seen at nearly full weight
// within 2 ms of its start (time resolution).
std::vector<float> asymmetric_window(std::size_t n, std::size_t fall) {  // see onset_window
  std::vector<float> window(n);
  const std::size_t rise = n - fall;
  for (std::size_t i = 0; i < n; ++i) {
    const double x =
        i < rise ? 0.5 * std::numbers::pi * static_cast<double>(i) / static_cast<double>(rise)
                 : 0.5 * std::numbers::pi *
                       (1.0 + static_cast<double>(i - rise) / static_cast<double>(fall));
    window[i] = static_cast<float>(std::sin(x) * std::sin(x));
  }
  return window;
}

// Log band energies of the frames whose newest sample is k * hop.
std::vector<float> log_spectra(const std::vector<float>& mono, const OnsetOptions& o,
                               int sample_rate, std::size_t& frame_count, std::size_t& bands_out) {
  const auto n = static_cast<std::size_t>(o.window_frames);
  const auto hop = static_cast<std::size_t>(o.hop_frames);
  const std::vector<Band> bands = make_bands(n, sample_rate, o.bands_per_octave);
  bands_out = bands.size();
  frame_count = mono.size() / hop + 1;
  std::vector<float> spectra(frame_count * bands.size(), 0.0f);
  if (bands.empty()) return spectra;

  const std::vector<float> window = onset_window(o, sample_rate);
  double window_energy = 0.0;
  for (float w : window) window_energy += static_cast<double>(w) * w;
  const std::unique_ptr<kiss_fftr_state, FftrDeleter> fft(
      kiss_fftr_alloc(static_cast<int>(n), 0, nullptr, nullptr));
  std::vector<float> frame(n);
  std::vector<kiss_fft_cpx> spectrum(n / 2 + 1);
  std::vector<float> magnitude(n / 2 + 1);
  const double silence = std::pow(10.0, o.silence_dbfs / 20.0);
  const double silence_energy = silence * silence * window_energy;
  // Full-scale sine -> magnitude ~1.
  const float norm = static_cast<float>(2.0 / std::sqrt(window_energy * static_cast<double>(n)));
  for (std::size_t k = 0; k < frame_count; ++k) {
    // Newest sample k * hop; older ones before the buffer are silence.
    const std::int64_t newest = static_cast<std::int64_t>(k * hop);
    double energy = 0.0;
    for (std::size_t i = 0; i < n; ++i) {
      const std::int64_t s = newest - static_cast<std::int64_t>(n - 1 - i);
      const float x = s >= 0 && s < static_cast<std::int64_t>(mono.size())
                          ? mono[static_cast<std::size_t>(s)]
                          : 0.0f;
      frame[i] = x * window[i];
      energy += static_cast<double>(frame[i]) * frame[i];
    }
    if (energy < silence_energy) continue;  // leaves zeros
    kiss_fftr(fft.get(), frame.data(), spectrum.data());
    for (std::size_t b = 0; b <= n / 2; ++b) {
      magnitude[b] =
          norm * std::sqrt(spectrum[b].r * spectrum[b].r + spectrum[b].i * spectrum[b].i);
    }
    float* row = &spectra[k * bands.size()];
    for (std::size_t b = 0; b < bands.size(); ++b) {
      const Band& band = bands[b];
      float sum = magnitude[band.peak];
      for (std::size_t i = band.first + 1; i < band.peak; ++i) {
        sum += magnitude[i] * static_cast<float>(i - band.first) /
               static_cast<float>(band.peak - band.first);
      }
      for (std::size_t i = band.peak + 1; i < band.last; ++i) {
        sum += magnitude[i] * static_cast<float>(band.last - i) /
               static_cast<float>(band.last - band.peak);
      }
      row[b] = std::log1p(static_cast<float>(o.compression) * sum);
    }
  }
  return spectra;
}

struct Analysis {
  std::vector<float> spectra;  // log band energies, frame-major
  std::vector<float> widened;  // each band's maximum with its neighbours
  std::size_t frame_count = 0, bands = 0, lag = 1, memory = 1;
  std::vector<double> flux;
};

// Power of `rising` bands at frame k (magnitudes back from the log scale).
double band_power(const std::vector<float>& spectra, std::size_t bands, std::size_t k,
                  const std::vector<std::size_t>& rising, const OnsetOptions& o) {
  double sum = 0.0;
  for (std::size_t b : rising) {
    const double m = std::expm1(static_cast<double>(spectra[k * bands + b])) / o.compression;
    sum += m * m;
  }
  return sum;
}

std::size_t fall_frames(const OnsetOptions& o, int sample_rate) {
  return std::clamp<std::size_t>(
      static_cast<std::size_t>(std::lround(o.leading_edge_s * sample_rate)), 1,
      static_cast<std::size_t>(o.window_frames) / 2);
}

Analysis analyse(const AudioBuffer& audio, const OnsetOptions& o) {
  Analysis out;
  std::vector<double>& flux = out.flux;
  if (audio.sample_rate <= 0 || o.window_frames < 16 || o.hop_frames < 1 ||
      (o.window_frames & (o.window_frames - 1)) != 0) {
    return out;
  }
  const std::vector<float> mono = mono_of(audio);
  if (mono.empty()) return out;
  std::size_t& frame_count = out.frame_count;
  std::size_t& bins = out.bands;
  out.spectra = log_spectra(mono, o, audio.sample_rate, frame_count, bins);
  const std::vector<float>& spectra = out.spectra;
  if (bins == 0) return out;

  const double hop_s = static_cast<double>(o.hop_frames) / audio.sample_rate;
  const auto lag = out.lag = static_cast<std::size_t>(std::max(1.0, std::round(o.lag_s / hop_s)));
  const auto memory =
      std::max(lag, static_cast<std::size_t>(std::max(1.0, std::round(o.memory_s / hop_s))));
  // Each band's maximum with its neighbours: a vibrato or a glide is not a new note.
  std::vector<float>& widened = out.widened;
  widened.resize(spectra.size());
  for (std::size_t k = 0; k < frame_count; ++k) {
    const float* row = &spectra[k * bins];
    float* row_out = &widened[k * bins];
    for (std::size_t b = 0; b < bins; ++b) {
      float m = row[b];
      if (b > 0) m = std::max(m, row[b - 1]);
      if (b + 1 < bins) m = std::max(m, row[b + 1]);
      row_out[b] = m;
    }
  }
  // The rise of each band over its loudest in [k - memory, k - lag]: a tremolo or a beating
  // chord goes up and down within that span and adds nothing; a new note's partials do. The
  // span's maximum by van Herk / Gil-Werman (block prefix and suffix maxima): three passes per
  // band whatever the span's length.
  flux.assign(frame_count, 0.0);
  const std::size_t span = memory - lag + 1;
  std::vector<float> prefix(frame_count), suffix(frame_count);
  for (std::size_t b = 0; b < bins; ++b) {
    for (std::size_t j = 0; j < frame_count; ++j) {
      const float x = widened[j * bins + b];
      prefix[j] = j % span == 0 ? x : std::max(prefix[j - 1], x);
    }
    for (std::size_t j = frame_count; j-- > 0;) {
      const float x = widened[j * bins + b];
      suffix[j] = j % span == span - 1 || j + 1 == frame_count ? x : std::max(suffix[j + 1], x);
    }
    for (std::size_t k = lag; k < frame_count; ++k) {
      const std::size_t last = k - lag;
      const float reference =
          last + 1 >= span ? std::max(suffix[last + 1 - span], prefix[last]) : prefix[last];
      flux[k] += std::max(0.0f, spectra[k * bins + b] - reference);
    }
  }
  return out;
}

}  // namespace

std::vector<double> onset_envelope(const AudioBuffer& audio, const OnsetOptions& o) {
  return analyse(audio, o).flux;
}

std::vector<float> onset_window(const OnsetOptions& o, int sample_rate) {
  return asymmetric_window(static_cast<std::size_t>(o.window_frames), fall_frames(o, sample_rate));
}

double onset_window_latency_s(const OnsetOptions& o, int sample_rate, double power_fraction) {
  // The detector's own step response: three steady tones (low, middle, high) start together at
  // t0 out of silence; how long until their bands reach power_fraction of their power.
  constexpr double kStart = 0.1;
  const auto length = static_cast<std::size_t>(0.4 * sample_rate);
  std::vector<float> mono(length, 0.0f);
  for (std::size_t i = static_cast<std::size_t>(kStart * sample_rate); i < length; ++i) {
    const double t = static_cast<double>(i) / sample_rate;
    double v = 0.0;
    for (double hz : {220.0, 880.0, 3520.0}) v += 0.1 * std::sin(2.0 * std::numbers::pi * hz * t);
    mono[i] = static_cast<float>(v);
  }
  std::size_t frames = 0, bands = 0;
  const std::vector<float> spectra = log_spectra(mono, o, sample_rate, frames, bands);
  const double hop_s = static_cast<double>(o.hop_frames) / sample_rate;
  const auto at = [&](double t) {
    return std::min(frames - 1, static_cast<std::size_t>(std::lround(t / hop_s)));
  };
  std::vector<std::size_t> rising;
  for (std::size_t b = 0; b < bands; ++b) {
    if (spectra[at(kStart + 0.15) * bands + b] > spectra[at(kStart - 0.01) * bands + b] + 1.0f) {
      rising.push_back(b);
    }
  }
  const auto power = [&](std::size_t k) { return band_power(spectra, bands, k, rising, o); };
  const double before = power(at(kStart - 0.01));
  const double after = power(at(kStart + 0.15));
  const double level = before + std::clamp(power_fraction, 0.0, 1.0) * (after - before);
  double previous = before;
  for (std::size_t k = at(kStart - 0.01); k < frames; ++k) {
    const double current = power(k);
    if (current >= level) {
      double index = static_cast<double>(k);
      if (current > previous) index -= (current - level) / (current - previous);
      return std::max(0.0, index * hop_s - kStart);
    }
    previous = current;
  }
  return 0.0;
}

std::vector<Onset> detect_onsets(const AudioBuffer& audio, const OnsetOptions& o) {
  std::vector<Onset> onsets;
  const Analysis analysis = analyse(audio, o);
  const std::vector<double>& flux = analysis.flux;
  if (flux.empty()) return onsets;
  const std::size_t bands = analysis.bands;
  const double latency_s = onset_window_latency_s(o, audio.sample_rate, o.power_fraction);
  const auto settle =
      static_cast<std::size_t>(std::round(o.settle_s * audio.sample_rate / o.hop_frames));
  std::vector<float> reference(bands);
  std::vector<std::size_t> rising;
  auto power = [&](std::size_t t) { return band_power(analysis.spectra, bands, t, rising, o); };
  const std::size_t frame_count = flux.size();
  const double hop_s = static_cast<double>(o.hop_frames) / audio.sample_rate;
  const double loudest = *std::max_element(flux.begin(), flux.end());
  if (loudest <= 0.0) return onsets;

  const auto gap = static_cast<std::size_t>(std::max(1.0, std::round(o.min_gap_s / hop_s)));
  const auto backtrack = static_cast<std::size_t>(std::max(1.0, std::round(o.backtrack_s / hop_s)));
  const auto local = static_cast<std::size_t>(std::max(1.0, std::round(o.local_window_s / hop_s)));
  // Prefix sums for the local means.
  std::vector<double> prefix(frame_count + 1, 0.0);
  for (std::size_t k = 0; k < frame_count; ++k) prefix[k + 1] = prefix[k] + flux[k];

  std::size_t last_peak = 0;
  bool have_peak = false;
  for (std::size_t k = 1; k < frame_count; ++k) {
    if (flux[k] <= 0.0) continue;
    const std::size_t from = k > gap ? k - gap : 0;
    const std::size_t to = std::min(frame_count, k + gap + 1);
    bool is_peak = true;
    for (std::size_t j = from; j < to && is_peak; ++j) {
      // On a plateau the first sample is the peak.
      if (flux[j] > flux[k] || (j < k && flux[j] == flux[k])) is_peak = false;
    }
    if (!is_peak) continue;
    const std::size_t mean_from = k > local ? k - local : 0;
    const std::size_t mean_to = std::min(frame_count, k + local / 2 + 1);
    const double mean =
        (prefix[mean_to] - prefix[mean_from]) / static_cast<double>(mean_to - mean_from);
    if (flux[k] - mean < o.threshold) continue;
    if (have_peak && k - last_peak < gap) continue;

    // The start of the rise: the flux's lowest in the backtrack span before the peak (not
    // before the previous onset's peak).
    std::size_t floor_index = k;
    for (std::size_t j = k; j + backtrack > k && j > 0; --j) {
      if (have_peak && j - 1 <= last_peak) break;
      if (flux[j - 1] < flux[floor_index]) floor_index = j - 1;
      if (flux[floor_index] <= 0.0) break;
    }
    // Heard where the bands that rise reach power_fraction of the power they gain: the
    // perceptual onset, not the first trace of sound (a slow attack is heard late).
    rising.clear();
    {
      const std::size_t lag = std::min(analysis.lag, k);
      const std::size_t from_j = k > analysis.memory ? k - analysis.memory : 0;
      std::copy_n(&analysis.widened[(k - lag) * bands], bands, reference.begin());
      for (std::size_t j = from_j; j < k - lag; ++j) {
        for (std::size_t b = 0; b < bands; ++b) {
          reference[b] = std::max(reference[b], analysis.widened[j * bands + b]);
        }
      }
      for (std::size_t b = 0; b < bands; ++b) {
        if (analysis.spectra[k * bands + b] > reference[b]) rising.push_back(b);
      }
    }
    const double before = power(floor_index);
    double after = before;
    for (std::size_t t = k; t < std::min(frame_count, k + settle + 1); ++t) {
      after = std::max(after, power(t));
    }
    const double level = before + o.power_fraction * (after - before);
    std::size_t j = floor_index;
    double previous = before;
    double current = before;
    for (; j < frame_count; ++j) {
      current = power(j);
      if (current >= level) break;
      previous = current;
    }
    // Between frame j - 1 (below the level) and j (at or above): interpolate.
    double index = static_cast<double>(j);
    if (j > floor_index && current > previous) index -= (current - level) / (current - previous);
    index = std::max(0.0, index - latency_s / hop_s);
    onsets.push_back({index * hop_s, flux[k] / loudest, flux[k]});
    last_peak = k;
    have_peak = true;
  }
  return onsets;
}

}  // namespace tutti::audio
