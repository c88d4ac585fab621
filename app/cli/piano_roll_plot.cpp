// SPDX-License-Identifier: MIT
#include <tutti/cli/piano_roll_plot.hpp>

#include <algorithm>
#include <charconv>
#include <cmath>

#include <tutti/cli/bitmap_font.hpp>
#include <tutti/image/png.hpp>

namespace tutti::cli {
namespace {

struct Rgb {
  std::uint8_t r, g, b;
};

struct HandColours {
  Rgb note, corridor, outline, path;
};
constexpr HandColours kRight{{40, 90, 200}, {200, 215, 245}, {120, 150, 220}, {10, 30, 110}};
constexpr HandColours kLeft{{200, 70, 40}, {245, 212, 200}, {220, 140, 120}, {110, 25, 10}};
constexpr Rgb kWhite{255, 255, 255};
constexpr Rgb kOctaveLine{200, 200, 200};
constexpr Rgb kSecondLine{232, 232, 232};

class Canvas {
 public:
  Canvas(int width, int height) : image_{width, height, {}} {
    image_.rgb.assign(std::size_t(width) * std::size_t(height) * 3, 255);
  }
  // Pixels outside the image are ignored, so callers need not clip.
  void set(int x, int y, Rgb c) {
    if (x < 0 || y < 0 || x >= image_.width || y >= image_.height) return;
    std::uint8_t* p =
        &image_.rgb[(std::size_t(y) * std::size_t(image_.width) + std::size_t(x)) * 3];
    p[0] = c.r;
    p[1] = c.g;
    p[2] = c.b;
  }
  // Multiplies the pixels by a tint (overlapping corridors of both hands stay visible).
  void tint(int x, int y, Rgb c) {
    if (x < 0 || y < 0 || x >= image_.width || y >= image_.height) return;
    std::uint8_t* p =
        &image_.rgb[(std::size_t(y) * std::size_t(image_.width) + std::size_t(x)) * 3];
    p[0] = std::uint8_t(p[0] * c.r / 255);
    p[1] = std::uint8_t(p[1] * c.g / 255);
    p[2] = std::uint8_t(p[2] * c.b / 255);
  }
  void fill(int x0, int y0, int x1, int y1, Rgb c, bool multiply = false) {
    for (int y = std::max(y0, 0); y <= std::min(y1, image_.height - 1); ++y) {
      for (int x = std::max(x0, 0); x <= std::min(x1, image_.width - 1); ++x) {
        multiply ? tint(x, y, c) : set(x, y, c);
      }
    }
  }
  void outline(int x0, int y0, int x1, int y1, Rgb c) {
    fill(x0, y0, x1, y0, c);
    fill(x0, y1, x1, y1, c);
    fill(x0, y0, x0, y1, c);
    fill(x1, y0, x1, y1, c);
  }
  // A number in the 3x5 font at `scale` pixels per font pixel, top-left at (x, y).
  void number(int x, int y, int value, int scale, Rgb c) {
    const std::string digits = std::to_string(value);
    for (char ch : digits) {
      const auto& glyph = kDigits3x5[std::size_t(ch - '0')];
      for (int row = 0; row < 5; ++row) {
        for (int col = 0; col < 3; ++col) {
          if ((glyph[std::size_t(row)] >> (2 - col)) & 1) {
            fill(x + col * scale, y + row * scale, x + (col + 1) * scale - 1,
                 y + (row + 1) * scale - 1, c);
          }
        }
      }
      x += 4 * scale;
    }
  }
  PlotImage take() { return std::move(image_); }

 private:
  PlotImage image_;
};

struct Frame {
  double t0 = 0, t1 = 1, px_per_s = kPlotPixelsPerSecond;
  double mm_lo = 0, mm_hi = 1;
  int x(double t) const { return kPlotMargin + int(std::floor((t - t0) * px_per_s)); }
  int y(double mm) const { return kPlotMargin + int(std::floor(mm_hi - mm)); }
};

double key_mm(const piano_model::Keyboard& keyboard, int key) {
  return keyboard.x_mm(std::clamp(key, keyboard.lowest_key(), keyboard.highest_key()));
}

Frame frame_for(const music::Score& score, const piano_performance::PianoPerformancePlan& plan,
                const piano_model::Keyboard& keyboard, std::optional<PlotWindow> window) {
  Frame f;
  f.t0 = window ? window->start_s : 0.0;
  f.t1 = window ? window->end_s : std::max(score.end_s, 0.001);
  const double seconds = f.t1 - f.t0;
  f.px_per_s = std::min(kPlotPixelsPerSecond, double(kPlotMaxWidth) / seconds);
  // Vertical range: every note and corridor visible in the window, plus half an octave.
  double lo = 1e300;
  double hi = -1e300;
  for (const music::Note& n : score.notes) {
    if (n.offset_s < f.t0 || n.onset_s > f.t1) continue;
    lo = std::min(lo, key_mm(keyboard, n.pitch));
    hi = std::max(hi, key_mm(keyboard, n.pitch));
  }
  for (const fingering_planner::HandPlan* hand : {&plan.fingering.right, &plan.fingering.left}) {
    for (const piano_model::HandCorridor& c : hand->corridors) {
      if (c.end_s < f.t0 || c.start_s > f.t1) continue;
      lo = std::min(lo, c.lo_mm);
      hi = std::max(hi, c.hi_mm);
    }
  }
  if (lo > hi) {
    lo = key_mm(keyboard, 60);
    hi = lo;
  }
  const double pad = 3.5 * keyboard.white_key_width_mm();
  f.mm_lo = std::max(lo - pad, key_mm(keyboard, keyboard.lowest_key()) - pad);
  f.mm_hi = std::min(hi + pad, key_mm(keyboard, keyboard.highest_key()) + pad);
  f.mm_lo = std::floor(f.mm_lo);
  f.mm_hi = std::ceil(f.mm_hi);
  return f;
}

void draw_grid(Canvas& canvas, const Frame& f, const piano_model::Keyboard& keyboard, int width,
               int height) {
  for (int s = int(std::ceil(f.t0)); s <= int(std::floor(f.t1)); ++s) {
    canvas.fill(f.x(s), kPlotMargin, f.x(s), height - kPlotMargin - 1, kSecondLine);
  }
  for (int key = keyboard.lowest_key(); key <= keyboard.highest_key(); ++key) {
    const double mm = keyboard.x_mm(key);
    if (key % 12 != 0 || mm < f.mm_lo || mm > f.mm_hi) continue;
    canvas.fill(kPlotMargin, f.y(mm), width - kPlotMargin - 1, f.y(mm), kOctaveLine);
  }
}

void draw_corridors(Canvas& canvas, const Frame& f, const piano_model::HandCorridors& corridors,
                    const HandColours& colours) {
  for (const piano_model::HandCorridor& c : corridors) {
    if (c.end_s < f.t0 || c.start_s > f.t1) continue;
    const int x0 = f.x(c.start_s);
    const int x1 = std::max(x0, f.x(c.end_s) - 1);
    canvas.fill(x0, f.y(c.hi_mm), x1, f.y(c.lo_mm), colours.corridor, /*multiply=*/true);
    canvas.outline(x0, f.y(c.hi_mm), x1, f.y(c.lo_mm), colours.outline);
  }
}

// Bars first, then (after the paths) the finger numbers, so a path never hides a number.
void draw_notes(Canvas& canvas, const Frame& f, const music::Score& score,
                const piano_model::Keyboard& keyboard, bool labels) {
  constexpr int kHalfBar = 7;  // px: a bar 15 px tall, room for a 10 px digit
  for (const music::Note& n : score.notes) {
    if (n.hand == music::Hand::unknown || n.offset_s < f.t0 || n.onset_s > f.t1) continue;
    const HandColours& colours = n.hand == music::Hand::right ? kRight : kLeft;
    const int y = f.y(key_mm(keyboard, n.pitch));
    const int x0 = f.x(n.onset_s);
    const int x1 = std::max(x0 + 8, f.x(n.offset_s) - 1);  // wide enough for the digit
    if (!labels) canvas.fill(x0, y - kHalfBar, x1, y + kHalfBar, colours.note);
    if (labels && n.finger > 0) canvas.number(x0 + 2, y - 5, n.finger, 2, kWhite);
  }
}

void draw_path(Canvas& canvas, const Frame& f, const spline_motion::HandPath& path, Rgb colour,
               int width) {
  if (path.empty()) return;
  int previous_y = 0;
  bool have_previous = false;
  for (int px = kPlotMargin; px < width - kPlotMargin; ++px) {
    const double t = f.t0 + (px - kPlotMargin + 0.5) / f.px_per_s;
    if (t < path.start_s() || t > path.end_s()) {
      have_previous = false;
      continue;
    }
    const int y = f.y(spline_motion::evaluate(path, t).x_mm);
    const int from = have_previous ? std::min(previous_y, y) : y;
    const int to = have_previous ? std::max(previous_y, y) : y;
    canvas.fill(px, from - 1, px, to + 1, colour);  // 3 px thick, continuous
    previous_y = y;
    have_previous = true;
  }
}

}  // namespace

Result<PlotWindow> parse_plot_window(const std::string& text) {
  const auto colon = text.find(':');
  PlotWindow w;
  const auto number = [](std::string_view s, double& v) {
    const auto [end, ec] = std::from_chars(s.data(), s.data() + s.size(), v);
    return ec == std::errc{} && end == s.data() + s.size() && std::isfinite(v);
  };
  if (colon == std::string::npos || !number(std::string_view(text).substr(0, colon), w.start_s) ||
      !number(std::string_view(text).substr(colon + 1), w.end_s) || w.start_s < 0.0 ||
      w.end_s <= w.start_s) {
    return Error{"--plot-seconds: expected A:B seconds with 0 <= A < B, got '" + text + "'"};
  }
  return w;
}

PlotImage plot_piano_roll(const music::Score& fingered,
                          const piano_performance::PianoPerformancePlan& plan,
                          const piano_model::Keyboard& keyboard, std::optional<PlotWindow> window) {
  const Frame f = frame_for(fingered, plan, keyboard, window);
  const int width = 2 * kPlotMargin + int(std::ceil((f.t1 - f.t0) * f.px_per_s));
  const int height = 2 * kPlotMargin + int(f.mm_hi - f.mm_lo) + 1;
  Canvas canvas(width, height);
  draw_grid(canvas, f, keyboard, width, height);
  draw_corridors(canvas, f, plan.fingering.left.corridors, kLeft);
  draw_corridors(canvas, f, plan.fingering.right.corridors, kRight);
  draw_notes(canvas, f, fingered, keyboard, /*labels=*/false);
  draw_path(canvas, f, plan.left_path, kLeft.path, width);
  draw_path(canvas, f, plan.right_path, kRight.path, width);
  draw_notes(canvas, f, fingered, keyboard, /*labels=*/true);
  // Margins stay white: nothing above may spill into them.
  canvas.fill(0, 0, width - 1, kPlotMargin - 1, kWhite);
  canvas.fill(0, height - kPlotMargin, width - 1, height - 1, kWhite);
  canvas.fill(0, 0, kPlotMargin - 1, height - 1, kWhite);
  canvas.fill(width - kPlotMargin, 0, width - 1, height - 1, kWhite);
  return canvas.take();
}

Status write_png(const std::filesystem::path& path, const PlotImage& image) {
  if (image.width <= 0 || image.height <= 0) return Error{path.string() + ": nothing to plot"};
  return image::write_png(path, image.rgb, static_cast<std::uint32_t>(image.width),
                          static_cast<std::uint32_t>(image.height), 3);
}

}  // namespace tutti::cli
