// SPDX-License-Identifier: MIT
#include <tutti/finger_motion/finger_motion_params.hpp>

#include <initializer_list>
#include <utility>

#include <nlohmann/json.hpp>

#include <tutti/piano_model/json_document.hpp>

namespace tutti::finger_motion {
namespace {

using piano_model::JsonReader;

// Reads `key` into `out`, requiring out > 0 (or >= 0 when `allow_zero`).
Status read_positive(const JsonReader& reader, const nlohmann::json& object,
                     const std::string& path, const char* key, double& out,
                     bool allow_zero = false) {
  auto value = reader.number(object, path, key);
  if (!value) return value.error();
  if (allow_zero ? *value < 0 : *value <= 0) {
    return reader.error(path + "/" + key, allow_zero ? "must not be negative" : "must be positive");
  }
  out = *value;
  return Status::success();
}

// One number of a table: its key, where it goes, whether 0 is allowed.
struct Field {
  const char* key;
  double* out;
  bool allow_zero;
};

// Reads each field of `fields` into place (read_positive); with `optional`, a field the object
// lacks keeps its default.
Status read_fields(const JsonReader& reader, const nlohmann::json& object, const std::string& path,
                   std::initializer_list<Field> fields, bool optional) {
  for (const Field& field : fields) {
    if (optional && !object.contains(field.key)) continue;
    if (auto ok = read_positive(reader, object, path, field.key, *field.out, field.allow_zero);
        !ok) {
      return ok;
    }
  }
  return Status::success();
}

Status read_keys(const JsonReader& reader, const nlohmann::json& document, KeyHeights& keys) {
  const std::string path = "/keys";
  if (!document.contains("keys")) return reader.error(path, "missing");
  const nlohmann::json& object = document.at("keys");
  if (auto ok = reader.check_keys(object, path,
                                  {"white_top_z_mm", "black_top_z_mm", "dip_mm", "hover_lift_mm",
                                   "black_front_y_mm", "black_press_in_mm", "white_press_in_mm",
                                   "pivot_y_mm"});
      !ok) {
    return ok;
  }
  auto white = reader.number(object, path, "white_top_z_mm");
  if (!white) return white.error();
  auto black = reader.number(object, path, "black_top_z_mm");
  if (!black) return black.error();
  if (!(*black > *white))
    return reader.error(path + "/black_top_z_mm", "must exceed white_top_z_mm");
  keys.white_top_z_mm = *white;
  keys.black_top_z_mm = *black;
  if (auto ok = read_positive(reader, object, path, "dip_mm", keys.dip_mm); !ok) return ok;
  // Optional (older files have none): where the black keys begin and where on them a finger lands.
  for (const auto& [key, out] : {std::pair{"black_front_y_mm", &keys.black_front_y_mm},
                                 std::pair{"black_press_in_mm", &keys.black_press_in_mm},
                                 std::pair{"white_press_in_mm", &keys.white_press_in_mm},
                                 std::pair{"pivot_y_mm", &keys.pivot_y_mm}}) {
    if (!object.contains(key)) continue;
    if (auto ok = read_positive(reader, object, path, key, *out, true); !ok) return ok;
  }
  if (keys.pivot_y_mm != 0.0 && !(keys.pivot_y_mm > keys.black_front_y_mm + keys.black_press_in_mm)) {
    return reader.error(path + "/pivot_y_mm", "must lie behind where black keys are pressed");
  }
  return read_positive(reader, object, path, "hover_lift_mm", keys.hover_lift_mm, true);
}

Status read_timing(const JsonReader& reader, const nlohmann::json& document, StrokeTiming& t) {
  const std::string path = "/timing";
  if (!document.contains("timing")) return reader.error(path, "missing");
  const nlohmann::json& object = document.at("timing");
  if (auto ok = reader.check_keys(object, path,
                                  {"press_lead_s", "move_min_s", "move_max_s", "move_s_per_mm",
                                   "shape_s", "release_s", "relax_time_constant_s", "reach_in_s",
                                   "reach_in_bridge_s"});
      !ok) {
    return ok;
  }
  if (auto ok = read_fields(reader, object, path,
                            {{"press_lead_s", &t.press_lead_s, false},
                             {"move_min_s", &t.move_min_s, false},
                             {"move_max_s", &t.move_max_s, false},
                             {"move_s_per_mm", &t.move_s_per_mm, true},
                             {"shape_s", &t.shape_s, false},
                             {"release_s", &t.release_s, false},
                             {"relax_time_constant_s", &t.relax_time_constant_s, false}},
                            false);
      !ok) {
    return ok;
  }
  // Optional (older files have none).
  if (auto ok = read_fields(reader, object, path,
                            {{"reach_in_s", &t.reach_in_s, false},
                             {"reach_in_bridge_s", &t.reach_in_bridge_s, true}},
                            true);
      !ok) {
    return ok;
  }
  if (t.move_max_s < t.move_min_s) return reader.error(path + "/move_max_s", "below move_min_s");
  return Status::success();
}

Status read_finger(const JsonReader& reader, const nlohmann::json& fingers, int finger,
                   FingerGeometry& out) {
  const std::string name = std::to_string(finger);
  const std::string path = "/fingers/" + name;
  if (!fingers.contains(name)) return reader.error(path, "missing");
  const nlohmann::json& object = fingers.at(name);
  if (auto ok = reader.check_keys(object, path,
                                  {"phalanges_mm", "root_y_mm", "root_z_mm", "neutral_bend_rad",
                                   "white_bend_rad", "black_bend_rad", "coupling", "pad_drop_mm"});
      !ok) {
    return ok;
  }
  if (!object.contains("phalanges_mm")) return reader.error(path + "/phalanges_mm", "missing");
  const nlohmann::json& lengths = object.at("phalanges_mm");
  if (!lengths.is_array() || lengths.size() != 3) {
    return reader.error(path + "/phalanges_mm", "expected 3 lengths in mm");
  }
  for (std::size_t i = 0; i < 3; ++i) {
    if (!lengths[i].is_number() || !(lengths[i].get<double>() > 0)) {
      return reader.error(path + "/phalanges_mm/" + std::to_string(i),
                          "expected a positive number");
    }
    out.phalanges_mm[i] = lengths[i].get<double>();
  }
  auto root_y = reader.number(object, path, "root_y_mm");
  if (!root_y) return root_y.error();
  out.root_y_mm = *root_y;
  if (auto ok = read_positive(reader, object, path, "root_z_mm", out.root_z_mm); !ok) return ok;
  const struct {
    const char* key;
    double* out;
  } bends[] = {{"neutral_bend_rad", &out.neutral_bend_rad},
               {"white_bend_rad", &out.white_bend_rad},
               {"black_bend_rad", &out.black_bend_rad}};
  for (const auto& bend : bends) {
    auto value = reader.number(object, path, bend.key);
    if (!value) return value.error();
    if (*value < 0 || *value > 1.6) {
      return reader.error(path + "/" + bend.key, "expected 0..1.6 rad");
    }
    *bend.out = *value;
  }
  auto coupling = reader.number(object, path, "coupling");
  if (!coupling) return coupling.error();
  if (*coupling < 0 || *coupling > 1.5) return reader.error(path + "/coupling", "expected 0..1.5");
  out.coupling = *coupling;
  auto pad_drop = reader.number_or(object, path, "pad_drop_mm", 0.0);
  if (!pad_drop) return pad_drop.error();
  if (*pad_drop < 0 || *pad_drop > 15) return reader.error(path + "/pad_drop_mm", "expected 0..15 mm");
  out.pad_drop_mm = *pad_drop;
  return Status::success();
}

// Optional (older files have none): every field of "pass_over" is optional too.
Status read_pass_over(const JsonReader& reader, const nlohmann::json& document,
                      PassOverParams& p) {
  const std::string path = "/pass_over";
  if (!document.contains("pass_over")) return Status::success();
  const nlohmann::json& object = document.at("pass_over");
  if (auto ok = reader.check_keys(object, path,
                                  {"lift_mm", "gap_mm", "crossed_mm", "ease_s", "sample_s"});
      !ok) {
    return ok;
  }
  return read_fields(reader, object, path,
                     {{"lift_mm", &p.lift_mm, true},  // 0: no hand is ever lifted
                      {"gap_mm", &p.gap_mm, false},
                      {"crossed_mm", &p.crossed_mm, false},
                      {"ease_s", &p.ease_s, false},
                      {"sample_s", &p.sample_s, false}},
                     true);
}

}  // namespace

Result<FingerMotionParams> finger_motion_params_from_json(const nlohmann::json& document,
                                                          const std::string& file_name) {
  const JsonReader reader(file_name);
  if (auto ok =
          reader.check_keys(document, "", {"description", "source", "keys", "timing", "fingers",
                                           "pass_over"});
      !ok) {
    return ok.error();
  }
  FingerMotionParams params;
  if (auto ok = read_keys(reader, document, params.keys); !ok) return ok.error();
  if (auto ok = read_timing(reader, document, params.timing); !ok) return ok.error();
  if (auto ok = read_pass_over(reader, document, params.pass_over); !ok) return ok.error();
  if (!document.contains("fingers")) return reader.error("/fingers", "missing");
  const nlohmann::json& fingers = document.at("fingers");
  if (auto ok = reader.check_keys(fingers, "/fingers", {"1", "2", "3", "4", "5"}); !ok) {
    return ok.error();
  }
  for (int finger = 1; finger <= 5; ++finger) {
    if (auto ok = read_finger(reader, fingers, finger,
                              params.fingers[static_cast<std::size_t>(finger - 1)]);
        !ok) {
      return ok.error();
    }
  }
  return params;
}

Result<FingerMotionParams> load_finger_motion_params(const std::filesystem::path& path) {
  auto document = piano_model::read_json_file(path);
  if (!document) return document.error();
  return finger_motion_params_from_json(*document, path.filename().string());
}

std::filesystem::path finger_motion_params_path(const std::filesystem::path& content_dir) {
  return content_dir / "piano" / "finger_motion.json";
}

}  // namespace tutti::finger_motion
