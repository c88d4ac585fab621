// SPDX-License-Identifier: MIT
#include <tutti/cli/rig_command.hpp>

#include <cmath>
#include <cstdio>
#include <fstream>
#include <memory>
#include <nlohmann/json.hpp>
#include <ostream>
#include <string>

#include <tutti/core/exit_codes.hpp>
#include <tutti/humanoid/humanoid.hpp>
#include <tutti/model/model_asset.hpp>
#include <tutti/scene/asset_mapping.hpp>
#include <tutti/stage/model_binding.hpp>

namespace tutti::cli {
namespace {

std::string axis_name(const glm::vec3& v) {
  const char* names[3] = {"X", "Y", "Z"};
  int best = 0;
  for (int c = 1; c < 3; ++c) {
    if (std::abs(v[c]) > std::abs(v[best])) best = c;
  }
  char text[64];
  if (std::abs(v[best]) > 0.98f) {
    std::snprintf(text, sizeof text, "%c%s", v[best] > 0 ? '+' : '-', names[best]);
  } else {
    std::snprintf(text, sizeof text, "(%.2f, %.2f, %.2f)", static_cast<double>(v.x),
                  static_cast<double>(v.y), static_cast<double>(v.z));
  }
  return text;
}

}  // namespace

int run_rig(const RigOptions& o, std::ostream& out, std::ostream& err) {
  // A mapping file (scene/asset_mapping.hpp) is JSON like a .gltf: name it for what it is.
  if (o.model.extension() == ".json") {
    std::ifstream in(o.model);
    const nlohmann::json doc = nlohmann::json::parse(in, nullptr, /*allow_exceptions=*/false);
    if (doc.is_object() && doc.contains("kind") && doc.contains("model") &&
        doc.at("model").is_string()) {
      err << "error: " << o.model.filename().string()
          << ": a mapping file, not a model (tutti rig reads the model it names: "
          << doc.at("model").get<std::string>() << ")\n";
      return kExitBadInput;
    }
  }
  auto model = model::load_model(o.model);
  if (!model) {
    err << "error: " << model.error().message << "\n";
    return kExitBadInput;
  }
  const humanoid::Humanoid h = humanoid::recognise(*model);
  const std::string file = o.model.string();
  const auto name_of = [&](int node) {
    return node < 0 ? std::string() : model->nodes[static_cast<std::size_t>(node)].name;
  };
  if (o.json) {
    nlohmann::json doc;
    doc["model"] = file;
    doc["method"] = h.method;
    doc["playable"] = h.playable();
    doc["metres_per_unit"] = h.metres_per_unit;
    doc["units_guessed"] = h.units_guessed;
    doc["height_m"] = h.height_m;
    doc["up"] = {h.up.x, h.up.y, h.up.z};
    doc["facing"] = {h.facing.x, h.facing.y, h.facing.z};
    doc["rest_pose"] = humanoid::rest_pose_name(h.rest);
    doc["arm_below_horizontal_deg"] = h.arm_below_horizontal_deg;
    doc["nodes"] = nlohmann::json::object();
    for (const auto& [role, node] : h.nodes) {
      if (node >= 0) doc["nodes"][std::string(role)] = name_of(node);
    }
    doc["missing_required"] = nlohmann::json::array();
    for (std::string_view r : h.missing_required) doc["missing_required"].push_back(r);
    doc["missing_optional"] = nlohmann::json::array();
    for (std::string_view r : h.missing_optional) doc["missing_optional"].push_back(r);
    doc["finger_bones"] = h.finger_bones;
    doc["morphs"] = nlohmann::json::object();
    for (const auto& [role, name] : h.morphs) doc["morphs"][role] = name;
    doc["notes"] = h.notes;
    doc["problems"] = h.problems;
    if (model->primitives_over_four_weights > 0) {
      doc["notes"].push_back(std::to_string(model->primitives_over_four_weights) +
                             " primitives had 8 weights per vertex: the 4 largest kept");
    }
    if (!o.mapping) out << doc.dump(2) << "\n";
  } else if (!o.mapping) {
    char line[256];
    out << "rig: " << file << " (" << model->nodes.size() << " nodes), recognised by " << h.method
        << "\n";
    std::snprintf(line, sizeof line,
                  "  units: %g m per unit%s; height %.2f m; up %s; facing %s; rest pose %s (upper "
                  "arms %.0f deg below horizontal)\n",
                  h.metres_per_unit, h.units_guessed ? " (guessed)" : "", h.height_m,
                  axis_name(h.up).c_str(), axis_name(h.facing).c_str(),
                  std::string(humanoid::rest_pose_name(h.rest)).c_str(), h.arm_below_horizontal_deg);
    out << line;
    int found = 0;
    for (const auto& [role, node] : h.nodes) found += node >= 0 ? 1 : 0;
    out << "  roles: " << found << " of " << h.nodes.size() << "\n";
    for (const auto& [role, node] : h.nodes) {
      if (node < 0) continue;
      std::snprintf(line, sizeof line, "    %-14s %s\n", std::string(role).c_str(),
                    name_of(node).c_str());
      out << line;
    }
    for (std::size_t side = 0; side < 2; ++side) {
      out << (side == 0 ? "  finger bones, left (thumb..little):" : "  finger bones, right:");
      for (const int n : h.finger_bones[side]) out << " " << n;
      out << (side == 1 ? "  (4: a metacarpal, skipped)\n" : "\n");
    }
    out << "  face morphs:";
    if (h.morphs.empty()) out << " none found";
    for (const auto& [role, name] : h.morphs) out << " " << role << " -> " << name << ";";
    out << "\n";
    if (!h.missing_required.empty()) {
      out << "  missing (required):";
      for (std::string_view r : h.missing_required) out << " " << r;
      out << "\n";
    }
    if (!h.missing_optional.empty()) {
      out << "  missing (optional):";
      for (std::string_view r : h.missing_optional) out << " " << r;
      out << "\n";
    }
    for (const std::string& problem : h.problems) out << "  problem: " << problem << "\n";
    for (const std::string& note : h.notes) out << "  note: " << note << "\n";
    if (model->primitives_over_four_weights > 0) {
      out << "  note: " << model->primitives_over_four_weights
          << " primitives had 8 weights per vertex: the 4 largest kept, renormalised\n";
    }
  }
  if (!h.playable()) {
    err << "error: " << file << ": not a humanoid tutti can play: " << h.what_is_missing() << "\n";
    return kExitBadInput;
  }
  if (o.mapping) {
    if (o.output.empty()) {
      err << "error: --mapping needs -o FILE.mapping.json\n";
      return kExitBadInput;
    }
    std::error_code ec;
    const std::filesystem::path base = o.output.parent_path().empty()
                                           ? std::filesystem::current_path()
                                           : std::filesystem::absolute(o.output.parent_path());
    const std::filesystem::path relative =
        std::filesystem::relative(std::filesystem::absolute(o.model), base, ec);
    const nlohmann::ordered_json doc = scene::asset_mapping_document(
        stage::recognised_character_mapping(h, *model, o.model), scene::character_kind(),
        ec || relative.empty() ? std::filesystem::absolute(o.model).string() : relative.string(),
        "Written by `tutti rig " + file + " --mapping` (" + h.method +
            "); edit any role to override what was recognised.");
    std::ofstream stream(o.output, std::ios::trunc);
    stream << doc.dump(2) << "\n";
    if (!stream) {
      err << "error: " << o.output.string() << ": cannot write\n";
      return kExitBadInput;
    }
    out << "rig: wrote " << o.output.string() << " (" << h.method << ")\n";
  }
  return kExitOk;
}

void register_rig_command(Commands& commands) {
  auto options = std::make_shared<RigOptions>();
  Command& command = commands.add(
      "rig",
      "What tutti recognises in a character model (.glb, .gltf, .vrm) by itself: roles and "
      "their nodes, units, height, facing, rest pose, fingers, face morphs");
  command.option("FILE", options->model, "character model").required();
  command.flag("--json", options->json, "print JSON instead of text");
  command.flag("--mapping", options->mapping, "write a mapping file (needs -o)");
  command.option("-o", options->output, "the mapping file to write");
  command.on_run([options](std::ostream& out, std::ostream& err) {
    return run_rig(*options, out, err);
  });
}

}  // namespace tutti::cli
