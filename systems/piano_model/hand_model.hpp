// SPDX-License-Identifier: MIT
#pragma once
// Which keys each finger reaches, relative to the hand's reference point (the resting middle
// finger), after Sekiguchi & Eiho (1999). Finger f on a key at x requires the reference point in
// [x - hi_f, x - lo_f]. Ranges are stored for the right hand in white-key widths in
// content/piano/hands.json and scaled by a size preset; the left hand is the mirror image
// (lo_left = -hi_right, hi_left = -lo_right). All values returned here are millimetres.

#include <array>
#include <filesystem>
#include <nlohmann/json_fwd.hpp>
#include <string>
#include <string_view>

#include <tutti/core/result.hpp>
#include <tutti/music/score.hpp>

namespace tutti::piano_model {

struct FingerRange {
  double lo_mm = 0.0;  // lowest offset of the fingertip from the reference point
  double hi_mm = 0.0;  // highest; lo_mm <= hi_mm
};

class HandModel {
 public:
  // `preset` empty = the file's default_preset. `white_key_width_mm` converts the file's units.
  // Errors: unknown preset (listing the file), bad ranges (lo > hi), unknown keys.
  static Result<HandModel> load(const std::filesystem::path& path, std::string_view preset,
                                double white_key_width_mm);
  static Result<HandModel> from_json(const nlohmann::json& document, const std::string& file_name,
                                     std::string_view preset, double white_key_width_mm);

  // finger 1 (thumb) .. 5 (little). `side` unknown is treated as right.
  const FingerRange& range(music::Hand side, int finger) const {
    const auto& table = side == music::Hand::left ? left_ : right_;
    return table[static_cast<std::size_t>(finger - 1)];
  }
  // The widest span one hand covers: thumb's lowest to little finger's highest (the same for
  // both hands, mirror images; an octave and a little for the medium hand).
  double reach_mm() const { return right_[4].hi_mm - right_[0].lo_mm; }
  const std::string& preset() const { return preset_; }
  double scale() const { return scale_; }

 private:
  std::array<FingerRange, 5> right_{};
  std::array<FingerRange, 5> left_{};
  std::string preset_;
  double scale_ = 1.0;
};

}  // namespace tutti::piano_model
