// SPDX-License-Identifier: MIT
#pragma once
// `tutti fingering --plot out.png`: the performance as a piano roll (Sekiguchi & Eiho's
// Figure 10, readable). x = time, y = keyboard position in millimetres (high keys on top, a grey
// line at every C, a light grey line every second). Per hand (right blue, left red): the
// fingering planner's corridors as tinted boxes, each note as a bar at its key's centre with its
// finger number, and the smoothed hand path as a dark line.
//
// Size: 200 px per second, scaled down so the width stays <= 4000 px; 1 px per mm plus a 10 px
// margin. Deterministic: the same plan gives the same PNG bytes.

#include <cstdint>
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include <tutti/core/result.hpp>
#include <tutti/music/score.hpp>
#include <tutti/piano_model/keyboard.hpp>
#include <tutti/piano_performance/performance_plan.hpp>

namespace tutti::cli {

struct PlotWindow {
  double start_s = 0.0;
  double end_s = 0.0;
};

// "A:B" seconds, 0 <= A < B. Errors start with "--plot-seconds: ".
Result<PlotWindow> parse_plot_window(const std::string& text);

struct PlotImage {
  int width = 0;
  int height = 0;
  std::vector<std::uint8_t> rgb;  // row-major, 3 bytes per pixel
};

inline constexpr int kPlotMaxWidth = 4000;
inline constexpr double kPlotPixelsPerSecond = 200.0;
inline constexpr int kPlotMargin = 10;

PlotImage plot_piano_roll(const music::Score& fingered,
                          const piano_performance::PianoPerformancePlan& plan,
                          const piano_model::Keyboard& keyboard, std::optional<PlotWindow> window);

// The plot as a PNG file (image/png.hpp: deterministic, written atomically).
Status write_png(const std::filesystem::path& path, const PlotImage& image);

}  // namespace tutti::cli
