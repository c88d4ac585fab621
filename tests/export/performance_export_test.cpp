// SPDX-License-Identifier: MIT
// tutti's glTF export, read back independently of the exporter: the file's own animation
// (glTF's LINEAR interpolation between the kept keys) put every node of the demo scenes where
// the stage put it at every exported frame, within half a millimetre; the clips are the
// performers plus the whole scene; the meshes load with tutti's model loader; a user's
// character exports on its own skeleton; the same stage gives the same bytes.
#include <gtest/gtest.h>
#include <tiny_gltf.h>
#include <unistd.h>

#include <cmath>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <functional>
#include <glm/gtc/matrix_transform.hpp>
#include <map>
#include <nlohmann/json.hpp>
#include <set>

#include <tutti/audio_sync/audio_clock.hpp>
#include <tutti/brass/brass_components.hpp>
#include <tutti/components/performer.hpp>
#include <tutti/performance/families.hpp>
#include <tutti/export/keyframe_reduction.hpp>
#include <tutti/export/scene_export.hpp>
#include <tutti/scene/asset_mapping.hpp>
#include <tutti/scene/load_scene.hpp>

namespace tutti::gltf_export {
namespace {

using nlohmann::json;
const std::filesystem::path kSource(TUTTI_SOURCE_DIR);

std::unique_ptr<stage::Stage> build(const std::filesystem::path& scene_file) {
  auto scene = scene::load_scene(scene_file, performance::scene_load_options());
  EXPECT_TRUE(scene) << scene.error().message;
  if (!scene) return nullptr;
  auto staged = performance::build_stage(*scene, {});
  EXPECT_TRUE(staged) << staged.error().message;
  return staged ? std::move(*staged) : nullptr;
}

// A .glb split into its JSON and BIN chunks, and float reads through accessors.
struct Glb {
  json document;
  std::vector<std::uint8_t> binary;

  static Glb parse(const std::vector<std::uint8_t>& bytes) {
    Glb glb;
    auto u32 = [&](std::size_t at) {
      std::uint32_t v = 0;
      std::memcpy(&v, bytes.data() + at, 4);
      return v;
    };
    EXPECT_EQ(u32(0), 0x46546C67u);
    EXPECT_EQ(u32(8), bytes.size());
    const std::uint32_t json_length = u32(12);
    glb.document = json::parse(bytes.begin() + 20, bytes.begin() + 20 + json_length);
    const std::size_t bin = 20 + json_length;
    if (bin < bytes.size()) {
      const std::uint32_t bin_length = u32(bin);
      glb.binary.assign(bytes.begin() + static_cast<std::ptrdiff_t>(bin + 8),
                        bytes.begin() + static_cast<std::ptrdiff_t>(bin + 8 + bin_length));
    }
    return glb;
  }

  std::vector<float> floats(int accessor) const {
    const json& a = document["accessors"][static_cast<std::size_t>(accessor)];
    EXPECT_EQ(a["componentType"], 5126);
    const json& view = document["bufferViews"][a["bufferView"].get<std::size_t>()];
    const std::map<std::string, std::size_t> widths{
        {"SCALAR", 1}, {"VEC3", 3}, {"VEC4", 4}, {"MAT4", 16}};
    const std::size_t n = a["count"].get<std::size_t>() * widths.at(a["type"]);
    std::vector<float> out(n);
    std::memcpy(out.data(), binary.data() + view["byteOffset"].get<std::size_t>(), n * 4);
    return out;
  }
};

struct Trs {
  glm::vec3 t{0.0f};
  glm::quat r{1.0f, 0.0f, 0.0f, 0.0f};
  glm::vec3 s{1.0f};
};

// Every node's local TRS at time `seconds` of animation `clip`, as a glTF player computes it.
std::vector<Trs> play(const Glb& glb, const json& clip, float seconds) {
  const json& nodes = glb.document["nodes"];
  std::vector<Trs> local(nodes.size());
  for (std::size_t i = 0; i < nodes.size(); ++i) {
    const json& n = nodes[i];
    const auto f = [&](const char* key, std::size_t c) { return n[key][c].get<float>(); };
    if (n.contains("translation"))
      local[i].t = {f("translation", 0), f("translation", 1), f("translation", 2)};
    if (n.contains("rotation"))
      local[i].r =
          glm::quat(f("rotation", 3), f("rotation", 0), f("rotation", 1), f("rotation", 2));
    if (n.contains("scale")) local[i].s = {f("scale", 0), f("scale", 1), f("scale", 2)};
  }
  for (const json& channel : clip["channels"]) {
    const json& sampler = clip["samplers"][channel["sampler"].get<std::size_t>()];
    EXPECT_EQ(sampler["interpolation"], "LINEAR");
    const std::vector<float> times = glb.floats(sampler["input"]);
    const std::vector<float> values = glb.floats(sampler["output"]);
    const std::string path = channel["target"]["path"];
    if (path == "weights") continue;
    const std::size_t width = path == "rotation" ? 4 : 3;
    std::size_t k = 0;
    while (k + 1 < times.size() && times[k + 1] <= seconds) ++k;
    const std::size_t next = std::min(k + 1, times.size() - 1);
    const float span = times[next] - times[k];
    const float u = span > 0.0f ? std::clamp((seconds - times[k]) / span, 0.0f, 1.0f) : 0.0f;
    const float* a = &values[k * width];
    const float* b = &values[next * width];
    Trs& target = local[channel["target"]["node"].get<std::size_t>()];
    if (path == "rotation") {
      target.r =
          slerp_shortest(glm::quat(a[3], a[0], a[1], a[2]), glm::quat(b[3], b[0], b[1], b[2]), u);
    } else {
      const glm::vec3 v = glm::mix(glm::vec3(a[0], a[1], a[2]), glm::vec3(b[0], b[1], b[2]), u);
      (path == "translation" ? target.t : target.s) = v;
    }
  }
  return local;
}

std::vector<glm::mat4> world_of(const Glb& glb, const std::vector<Trs>& local) {
  const json& nodes = glb.document["nodes"];
  std::vector<int> parent(nodes.size(), -1);
  for (std::size_t i = 0; i < nodes.size(); ++i) {
    if (!nodes[i].contains("children")) continue;
    for (const json& c : nodes[i]["children"]) parent[c.get<std::size_t>()] = static_cast<int>(i);
  }
  std::vector<glm::mat4> world(nodes.size());
  std::vector<bool> done(nodes.size(), false);
  std::function<const glm::mat4&(std::size_t)> get = [&](std::size_t i) -> const glm::mat4& {
    if (!done[i]) {
      const glm::mat4 m = glm::translate(glm::mat4(1.0f), local[i].t) * glm::mat4_cast(local[i].r) *
                          glm::scale(glm::mat4(1.0f), local[i].s);
      world[i] = parent[i] < 0 ? m : get(static_cast<std::size_t>(parent[i])) * m;
      done[i] = true;
    }
    return world[i];
  };
  for (std::size_t i = 0; i < nodes.size(); ++i) get(i);
  return world;
}

const json* clip_named(const Glb& glb, const std::string& name) {
  for (const json& a : glb.document["animations"]) {
    if (a["name"] == name) return &a;
  }
  return nullptr;
}

// Exports `frames` frames from `first` and checks, at every frame, every node of every placed
// model against the stage's own world matrices. Returns the worst error in metres.
float worst_world_error(stage::Stage& stage, int fps, std::int64_t first, std::int64_t frames,
                        ExportSummary* summary_out = nullptr) {
  auto exported = export_performance(stage, {fps, first, frames});
  EXPECT_TRUE(exported) << exported.error().message;
  if (!exported) return 1e9f;
  const Glb glb = Glb::parse(exported->glb);
  const json* whole = clip_named(glb, whole_scene_clip_name(stage));
  EXPECT_NE(whole, nullptr);
  if (whole == nullptr) return 1e9f;
  const std::vector<InstanceLabel> labels = label_instances(stage);
  // Instance i's root is the node named labels[i].name; model node j follows it at root + 1 + j.
  std::vector<std::size_t> roots;
  for (const InstanceLabel& label : labels) {
    const json& nodes = glb.document["nodes"];
    std::size_t found = nodes.size();
    for (std::size_t n = 0; n < nodes.size(); ++n) {
      if (nodes[n].value("name", "") == label.name && found == nodes.size()) found = n;
    }
    EXPECT_LT(found, nodes.size()) << label.name;
    roots.push_back(found);
  }
  float worst = 0.0f;
  std::vector<glm::mat4> expected;
  for (std::int64_t k = 0; k < frames; ++k) {
    stage::evaluate_stage(stage, audio_sync::offline_frame_time(stage.start_s(), fps, first + k));
    const std::vector<glm::mat4> world =
        world_of(glb, play(glb, *whole, static_cast<float>(static_cast<double>(k) / fps)));
    for (std::size_t i = 0; i < stage.instances().size(); ++i) {
      const stage::PlacedModel& placed = stage.placed(i);
      const model::ModelAsset& asset = *placed.asset;
      expected.assign(asset.nodes.size(), glm::mat4(1.0f));
      model::compute_world_matrices(asset, placed.pose, placed.root, expected);
      for (std::size_t j = 0; j < asset.nodes.size(); ++j) {
        const model::Node& node = asset.nodes[j];
        if (node.skin >= 0 && node.mesh >= 0 && node.children.empty()) continue;  // at the root
        const glm::mat4& got = world[roots[i] + 1 + j];
        EXPECT_EQ(glb.document["nodes"][roots[i] + 1 + j].value("name", ""), node.name);
        for (const glm::vec4 p : {glm::vec4(0, 0, 0, 1), glm::vec4(0.1f, 0.1f, 0.1f, 1)}) {
          worst = std::max(worst, glm::length(glm::vec3(got * p) - glm::vec3(expected[j] * p)));
        }
      }
    }
  }
  if (summary_out) *summary_out = *exported;
  return worst;
}

TEST(PerformanceExport, ThePianoDemoPlaysBackWithinHalfAMillimetre) {
  auto stage = build(kSource / "content" / "scenes" / "piano.json");
  ASSERT_TRUE(stage);
  ExportSummary summary;
  // Four seconds from 2 s: both hands play, keys go down, the body leans.
  const float worst = worst_world_error(*stage, 30, 60, 120, &summary);
  EXPECT_LT(worst, 5e-4f);
  std::printf("piano: worst node error %.4f mm, %zu of %zu samples kept\n", worst * 1000.0f,
              summary.keys, summary.samples);
  EXPECT_LT(summary.keys, summary.samples / 2) << "reduction keeps less than half the samples";
  ASSERT_EQ(summary.clips.size(), 2u);
  EXPECT_EQ(summary.clips[0].name, "pianist");
  EXPECT_EQ(summary.clips[1].name, "scene");
  EXPECT_GT(summary.clips[0].channels, 20u) << "keys, fingers, wrists and arms move";
}

TEST(PerformanceExport, TheQuartetPlaysBackWithinHalfAMillimetre) {
  auto stage = build(kSource / "content" / "scenes" / "quartet.json");
  ASSERT_TRUE(stage);
  ExportSummary summary;
  const float worst = worst_world_error(*stage, 24, 48, 96, &summary);
  EXPECT_LT(worst, 5e-4f);
  std::printf("quartet: worst node error %.4f mm, %zu of %zu samples kept\n", worst * 1000.0f,
              summary.keys, summary.samples);
  ASSERT_EQ(summary.clips.size(), stage->performers().size() + 1);
  for (std::size_t i = 0; i < stage->performers().size(); ++i) {
    EXPECT_EQ(summary.clips[i].name,
              stage->world().get<components::Performer>(stage->performers()[i]).name);
    EXPECT_GT(summary.clips[i].channels, 10u);
  }
}

TEST(PerformanceExport, MouthMorphsValvesAndKeysAreAnimated) {
  auto stage = build(kSource / "content" / "scenes" / "quartet.json");
  ASSERT_TRUE(stage);
  auto exported = export_performance(*stage, {30, 0, 30 * 12});
  ASSERT_TRUE(exported) << exported.error().message;
  const Glb glb = Glb::parse(exported->glb);
  std::set<std::string> animated;  // "node name/path"
  for (const json& channel : clip_named(glb, "scene")->at("channels")) {
    const json& node = glb.document["nodes"][channel["target"]["node"].get<std::size_t>()];
    animated.insert(node.value("name", "?") + "/" + channel["target"]["path"].get<std::string>());
  }
  EXPECT_TRUE(animated.count("valve_1/translation")) << "a trumpet valve moves";
  EXPECT_TRUE(animated.count("slide/translation")) << "the trombone slide moves";
  bool weights = false;
  for (const std::string& a : animated) weights = weights || a.ends_with("/weights");
  EXPECT_TRUE(weights) << "mouth morphs are animated";
}

TEST(PerformanceExport, TheFileLoadsWithTuttisModelLoader) {
  auto stage = build(kSource / "content" / "scenes" / "piano.json");
  ASSERT_TRUE(stage);
  auto exported = export_performance(*stage, {30, 0, 10});
  ASSERT_TRUE(exported) << exported.error().message;
  auto loaded = model::load_model_from_memory(exported->glb, "export.glb");
  ASSERT_TRUE(loaded) << loaded.error().message;
  std::size_t vertices = 0;
  for (const auto& m : stage->models()) vertices += m->vertices.size();
  EXPECT_GT(loaded->vertices.size(), 0u);
  EXPECT_LE(loaded->vertices.size(), vertices) << "each model's meshes are written once";
  EXPECT_EQ(loaded->skins.size(), exported->skins);
  EXPECT_NE(loaded->find_node("key_60"), -1);
  EXPECT_NE(loaded->find_node("piano"), -1);
}

TEST(PerformanceExport, TheSameStageGivesTheSameBytes) {
  auto a = build(kSource / "content" / "scenes" / "quartet.json");
  auto b = build(kSource / "content" / "scenes" / "quartet.json");
  ASSERT_TRUE(a && b);
  auto first = export_performance(*a, {30, 100, 60});
  auto second = export_performance(*b, {30, 100, 60});
  ASSERT_TRUE(first && second);
  EXPECT_EQ(first->glb, second->glb);
  auto again = export_performance(*a, {30, 100, 60});  // a stage already posed elsewhere
  ASSERT_TRUE(again);
  EXPECT_EQ(first->glb, again->glb);
}

// Players called "scene" and "pianist" keep their names; the whole-scene clip steps aside.
TEST(PerformanceExport, ClipNamesStayDistinct) {
  std::ifstream in(kSource / "content" / "scenes" / "quartet.json");
  json document = json::parse(in);
  document["performers"][0]["name"] = "scene";
  document["performers"][1]["name"] = "pianist";
  const std::filesystem::path file = std::filesystem::temp_directory_path() /
                                     ("tutti-export-names-" + std::to_string(getpid()) + ".json");
  // ... and a pianist, playing a second piece.
  document["music"] = json::array({(kSource / "content" / "music" / "quartet.musicxml").string(),
                                   (kSource / "content" / "music" / "ode_to_joy.musicxml").string()});
  document["pianist"] = {{"parts", {"Piano"}}, {"music_file", 1}, {"position_m", {0, 0, 3}}};
  std::ofstream(file) << document.dump();
  auto stage = build(file);
  std::filesystem::remove(file);
  ASSERT_TRUE(stage);
  auto exported = export_performance(*stage, {30, 60, 30});
  ASSERT_TRUE(exported) << exported.error().message;
  std::set<std::string> names;
  for (const ClipSummary& clip : exported->clips) names.insert(clip.name);
  EXPECT_EQ(names.size(), exported->clips.size());
  EXPECT_TRUE(names.count("scene") && names.count("pianist") && names.count("scene (all)") &&
              names.count("pianist (piano)"));
  EXPECT_EQ(clip_names(*stage).back(), "pianist (piano)");
}

TEST(PerformanceExport, AnEmptyRangeIsAnError) {
  auto stage = build(kSource / "content" / "scenes" / "piano.json");
  ASSERT_TRUE(stage);
  auto none = export_performance(*stage, {30, 0, 0});
  ASSERT_FALSE(none);
  EXPECT_NE(none.error().message.find("nothing to export"), std::string::npos);
}

// The generated performer with every node renamed "User:..." and a morph renamed: a user's
// character through a mapping file keeps its own skeleton and names in the export.
TEST(PerformanceExport, AUsersCharacterExportsOnItsOwnSkeleton) {
  const std::filesystem::path dir =
      std::filesystem::temp_directory_path() / ("tutti-export-test-" + std::to_string(getpid()));
  std::filesystem::remove_all(dir);
  std::filesystem::create_directories(dir);
  tinygltf::TinyGLTF io;
  tinygltf::Model model;
  std::string error, warning;
  ASSERT_TRUE(io.LoadBinaryFromFile(&model, &error, &warning,
                                    (stage::default_asset_dir() / "performer.glb").string()))
      << error;
  std::set<std::string> names;
  for (tinygltf::Node& node : model.nodes) {
    node.name = "User:" + node.name;
    names.insert(node.name);
  }
  ASSERT_TRUE(io.WriteGltfSceneToFile(&model, (dir / "user_character.glb").string(), true, true,
                                      false, true));
  json nodes = json::object();
  for (const std::string_view role : scene::character_kind().node_roles) {
    if (names.count("User:" + std::string(role)))
      nodes[std::string(role)] = "User:" + std::string(role);
  }
  std::ofstream(dir / "character.mapping.json") << json{
      {"model", "user_character.glb"},
      {"kind", "character"},
      {"nodes", nodes},
      {"morphs",
       {{"tension", "tension"}, {"open", "open"}}}}.dump();
  std::ofstream(dir / "scene.json")
      << json{{"music", (kSource / "content" / "music" / "quartet.musicxml").string()},
              {"performers", json::array({{{"name", "Robin"},
                                           {"instrument", "trumpet_bb"},
                                           {"part", "Trumpet 1"},
                                           {"position_m", {0, 0, 0}},
                                           {"character", "character.mapping.json"}}})},
              {"cameras",
               json::array(
                   {{{"name", "c"}, {"position_m", {0, 1.5, 3}}, {"target_m", {0, 1.5, 0}}}})}}
             .dump();
  auto stage = build(dir / "scene.json");
  ASSERT_TRUE(stage);
  ASSERT_TRUE(stage->world()
                  .get<brass::BrassRig>(stage->find_performer("brass", 0))
                  .body_retarget.has_value());
  const float worst = worst_world_error(*stage, 15, 0, 300);
  EXPECT_LT(worst, 5e-4f);
  auto exported = export_performance(*stage, {15, 0, 300});
  ASSERT_TRUE(exported);
  const Glb glb = Glb::parse(exported->glb);
  std::set<std::string> animated;
  for (const json& channel : clip_named(glb, "Robin")->at("channels")) {
    animated.insert(
        glb.document["nodes"][channel["target"]["node"].get<std::size_t>()].value("name", ""));
  }
  std::string list;
  for (const std::string& a : animated) list += a + " ";
  EXPECT_TRUE(animated.count("User:performer_face_mesh"))
      << "the mouth morphs play on the user's mesh; animated: " << list;
  std::size_t user_joints = 0;
  for (const json& skin : glb.document["skins"]) {
    for (const json& joint : skin["joints"]) {
      const std::string name = glb.document["nodes"][joint.get<std::size_t>()].value("name", "");
      user_joints += name.rfind("User:", 0) == 0 ? 1 : 0;
    }
  }
  EXPECT_GT(user_joints, 20u) << "the skin is the user's skeleton";
  std::filesystem::remove_all(dir);
}

}  // namespace
}  // namespace tutti::gltf_export
