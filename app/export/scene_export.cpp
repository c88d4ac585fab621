// SPDX-License-Identifier: MIT
#include <tutti/export/scene_export.hpp>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <map>
#include <nlohmann/json.hpp>
#include <set>

#include <tutti/audio_sync/audio_clock.hpp>
#include <tutti/performance/performance.hpp>
#include <tutti/export/glb_builder.hpp>
#include <tutti/stage/contact_recorder.hpp>

namespace tutti::gltf_export {
namespace {

using model::ModelAsset;
using model::NodeTransform;
using nlohmann::json;

NodeTransform node_transform(const performance::Trs& t) {
  NodeTransform out;
  out.translation = {t.translation[0], t.translation[1], t.translation[2]};
  out.rotation = glm::quat(t.rotation[3], t.rotation[0], t.rotation[1], t.rotation[2]);
  out.scale = {t.scale[0], t.scale[1], t.scale[2]};
  return out;
}

json vec_json(const glm::vec3& v) { return json::array({v.x, v.y, v.z}); }
json quat_json(const glm::quat& q) { return json::array({q.x, q.y, q.z, q.w}); }

void put_transform(json& node, const NodeTransform& t) {
  if (t.translation != glm::vec3(0.0f)) node["translation"] = vec_json(t.translation);
  if (t.rotation != glm::quat(1.0f, 0.0f, 0.0f, 0.0f)) node["rotation"] = quat_json(t.rotation);
  if (t.scale != glm::vec3(1.0f)) node["scale"] = vec_json(t.scale);
}

std::string stem_of(const std::string& file) { return std::filesystem::path(file).stem().string(); }

// One placed model over the exported frames. Node n's transform at frame k is locals[k * nodes +
// n]; the instance root's is roots[k]; morph weights are weights[k * weight_count + w].
struct InstanceSamples {
  std::vector<NodeTransform> roots;
  std::vector<NodeTransform> locals;
  std::vector<float> weights;
};

std::vector<InstanceSamples> sample(const stage::Stage& stage, const ExportRange& range,
                                    stage::ContactRecorder& contacts) {
  const std::size_t instances = stage.instances().size();
  std::vector<InstanceSamples> samples(instances);
  const auto frames = static_cast<std::size_t>(range.frame_count);
  for (std::size_t i = 0; i < instances; ++i) {
    const stage::PlacedModel& placed = stage.placed(i);
    samples[i].roots.reserve(frames);
    samples[i].locals.reserve(frames * placed.pose.local.size());
    samples[i].weights.reserve(frames * placed.pose.morph_weights.size());
  }
  // Frame k is posed at the render's time for it (the offline frame clock), in a context of
  // the export's own: the stage itself is left as it was.
  stage::StageContext context = stage.make_context();
  std::vector<performance::ModelPose> poses;
  for (std::int64_t k = 0; k < range.frame_count; ++k) {
    const double t =
        audio_sync::offline_frame_time(stage.start_s(), range.fps, range.first_frame + k);
    stage.run(context, {t, 1.0 / range.fps});
    // The poses a host reads from tutti::performance (rotations normalised, roots as TRS).
    performance::read_poses(stage, context, poses);
    contacts.record(stage, context.world(), static_cast<double>(k) / range.fps);  // clip time
    for (std::size_t i = 0; i < instances; ++i) {
      const performance::ModelPose& pose = poses[i];
      InstanceSamples& s = samples[i];
      s.roots.push_back(node_transform(pose.root));
      for (const performance::Trs& local : pose.local) s.locals.push_back(node_transform(local));
      s.weights.insert(s.weights.end(), pose.morph_weights.begin(), pose.morph_weights.end());
    }
  }
  return samples;
}

// Where one model's shared data went in the file.
struct WrittenModel {
  bool written = false;
  int first_mesh = 0;
  std::vector<int> inverse_binds;  // accessor per skin
};

class Writer {
 public:
  Writer(const stage::Stage& stage, const ExportRange& range, const KeyTolerances& tolerances)
      : stage_(stage), range_(range), tolerances_(tolerances) {}

  ExportSummary run() {
    const std::vector<InstanceLabel> labels = label_instances(stage_);
    stage::ContactRecorder recorder;
    const std::vector<InstanceSamples> samples = sample(stage_, range_, recorder);
    ExportSummary summary;

    json& asset = builder_.document()["asset"];
    asset = {{"version", "2.0"}, {"generator", "tutti export"}};
    asset["extras"] = {{"tutti",
                        {{"scene", stage_.scene().source},
                         {"fps", range_.fps},
                         {"first_frame", range_.first_frame},
                         {"frames", range_.frame_count},
                         {"start_s", audio_sync::offline_frame_time(stage_.start_s(), range_.fps,
                                                                    range_.first_frame)},
                         {"tolerances",
                          {{"translation_m", tolerances_.translation_m},
                           {"rotation_deg", glm::degrees(tolerances_.rotation_rad)},
                           {"scale", tolerances_.scale},
                           {"weight", tolerances_.weight}}}}}};

    written_.resize(stage_.models().size());
    std::vector<int> scene_roots;
    std::vector<std::string> clip_order;
    for (const std::string& clip : clip_names(stage_)) clip_order.push_back(clip);

    for (std::size_t i = 0; i < stage_.instances().size(); ++i) {
      write_instance(i, labels[i], samples[i], scene_roots);
    }
    write_contacts(recorder.contacts(), labels);
    builder_.document()["scenes"] =
        json::array({{{"name", stem_of(stage_.scene().source)}, {"nodes", scene_roots}}});
    builder_.document()["scene"] = 0;

    // Per-performer clips (scene order), then the whole scene with every channel.
    for (const std::string& clip : clip_order) {
      std::vector<const Channel*> channels;
      for (const Channel& c : channels_) {
        if (c.clip == clip) channels.push_back(&c);
      }
      if (!channels.empty()) summary.clips.push_back(write_animation(clip, channels));
    }
    std::vector<const Channel*> all;
    for (const Channel& c : channels_) all.push_back(&c);
    if (!all.empty()) summary.clips.push_back(write_animation(whole_scene_clip_name(stage_), all));

    summary.nodes = builder_.document()["nodes"].size();
    summary.meshes =
        builder_.document().contains("meshes") ? builder_.document()["meshes"].size() : 0;
    summary.skins = builder_.document().contains("skins") ? builder_.document()["skins"].size() : 0;
    summary.samples = samples_;
    for (const Channel& c : channels_) summary.keys += c.keys;
    summary.duration_s = static_cast<double>(range_.frame_count - 1) / range_.fps;
    summary.glb = builder_.finish();
    return summary;
  }

 private:
  struct Channel {
    std::string clip;
    int node = 0;
    const char* path = "";
    int input = 0;
    int output = 0;
    std::size_t keys = 0;
  };

  // The root `extras.tutti.contacts` (docs/embedding.md): who touches what, where and when, in
  // the clip's time. Nodes by the name of their instance's root node and their own name, and
  // by their index in this file.
  void write_contacts(const std::vector<stage::Contact>& contacts,
                      const std::vector<InstanceLabel>& labels) {
    const auto micrometres = [](double m) { return std::round(m * 1e6) / 1e6; };
    const auto node_name = [this](std::size_t instance, int node) {
      const ModelAsset& asset = *stage_.models()[stage_.placed(instance).model];
      return asset.nodes[static_cast<std::size_t>(node)].name;
    };
    json out = json::array();
    for (const stage::Contact& contact : contacts) {
      if (contact.body_instance >= labels.size() || contact.part_instance >= labels.size()) continue;
      json spans = json::array();
      for (const stage::ContactSpan& span : contact.spans) {
        json item = {{"from_s", span.from_s},
                     {"to_s", span.to_s},
                     {"part_point_m", json::array({micrometres(span.part_point_m.x),
                                                   micrometres(span.part_point_m.y),
                                                   micrometres(span.part_point_m.z)})}};
        if (span.midi >= 0) item["midi"] = span.midi;
        spans.push_back(std::move(item));
      }
      out.push_back({{"performer", labels[contact.body_instance].performer},
                     {"body_root", labels[contact.body_instance].name},
                     {"body_node", node_name(contact.body_instance, contact.body_node)},
                     {"body_node_index", instance_root_[contact.body_instance] + 1 + contact.body_node},
                     {"part_root", labels[contact.part_instance].name},
                     {"part_node", node_name(contact.part_instance, contact.part_node)},
                     {"part_node_index", instance_root_[contact.part_instance] + 1 + contact.part_node},
                     {"spans", std::move(spans)}});
    }
    builder_.document()["extras"] = {{"tutti", {{"contacts", std::move(out)}}}};
  }

  const WrittenModel& model_data(std::uint32_t m) {
    WrittenModel& w = written_[m];
    if (w.written) return w;
    w.written = true;
    const ModelAsset& asset = *stage_.models()[m];
    std::vector<bool> skinned(asset.meshes.size(), false);
    for (const model::Node& node : asset.nodes) {
      if (node.mesh >= 0 && node.skin >= 0) skinned[static_cast<std::size_t>(node.mesh)] = true;
    }
    const int first_material = materials(asset);
    for (std::size_t mesh = 0; mesh < asset.meshes.size(); ++mesh) {
      const int index = write_mesh(asset, asset.meshes[mesh], skinned[mesh], first_material);
      if (mesh == 0) w.first_mesh = index;
    }
    for (const model::Skin& skin : asset.skins) {
      std::vector<float> matrices;
      for (const glm::mat4& m4 : skin.inverse_bind) {
        for (int c = 0; c < 4; ++c) {
          for (int r = 0; r < 4; ++r) matrices.push_back(m4[c][r]);
        }
      }
      w.inverse_binds.push_back(builder_.add_floats(matrices, "MAT4", BufferTarget::none, false));
    }
    return w;
  }

  int materials(const ModelAsset& asset) {
    const int first = builder_.document().contains("materials")
                          ? static_cast<int>(builder_.document()["materials"].size())
                          : 0;
    for (const model::Material& m : asset.materials) {
      const auto unit = [](float v) { return std::clamp(v, 0.0f, 1.0f); };
      json material = {
          {"pbrMetallicRoughness",
           {{"baseColorFactor", json::array({unit(m.base_color.r), unit(m.base_color.g),
                                             unit(m.base_color.b), unit(m.base_color.a)})},
            {"metallicFactor", unit(m.metallic)},
            {"roughnessFactor", unit(m.roughness)}}}};
      if (!m.name.empty()) material["name"] = m.name;
      if (m.emissive != glm::vec3(0.0f)) {
        material["emissiveFactor"] =
            json::array({unit(m.emissive.r), unit(m.emissive.g), unit(m.emissive.b)});
      }
      if (m.alpha_mode == model::AlphaMode::blend) material["alphaMode"] = "BLEND";
      if (m.alpha_mode == model::AlphaMode::mask) {
        material["alphaMode"] = "MASK";
        material["alphaCutoff"] = m.alpha_cutoff;
      }
      if (m.double_sided) material["doubleSided"] = true;
      const auto info = [&](const model::TextureRef& ref, const char* amount) -> json {
        json out = {{"index", texture_index(asset, ref.texture)}};
        if (ref.texcoord != 0) out["texCoord"] = ref.texcoord;
        if (amount != nullptr) out[amount] = ref.amount;
        if (ref.transformed) {
          out["extensions"]["KHR_texture_transform"] = {
              {"offset", {ref.offset.x, ref.offset.y}},
              {"rotation", ref.rotation},
              {"scale", {ref.scale.x, ref.scale.y}}};
          builder_.use_extension("KHR_texture_transform", false);
        }
        return out;
      };
      if (m.base_color_texture.present()) {
        material["pbrMetallicRoughness"]["baseColorTexture"] = info(m.base_color_texture, nullptr);
      }
      if (m.metallic_roughness_texture.present()) {
        material["pbrMetallicRoughness"]["metallicRoughnessTexture"] =
            info(m.metallic_roughness_texture, nullptr);
      }
      if (m.normal_texture.present()) material["normalTexture"] = info(m.normal_texture, "scale");
      if (m.occlusion_texture.present()) {
        material["occlusionTexture"] = info(m.occlusion_texture, "strength");
      }
      if (m.emissive_texture.present()) material["emissiveTexture"] = info(m.emissive_texture, nullptr);
      builder_.append("materials", std::move(material));
    }
    return first;
  }

  // The export's texture for the model's texture `index`: its image embedded as the file had it
  // (PNG, JPEG, or WebP through EXT_texture_webp), its sampler; written once per model.
  int texture_index(const ModelAsset& asset, int index) {
    const auto key = std::pair<const ModelAsset*, int>(&asset, index);
    if (const auto found = textures_.find(key); found != textures_.end()) return found->second;
    const model::Texture& texture = asset.textures[static_cast<std::size_t>(index)];
    const model::Image& image = asset.images[static_cast<std::size_t>(texture.image)];
    json written_image = {{"bufferView", builder_.add_image_bytes(image.encoded)},
                          {"mimeType", image.mime_type}};
    if (!image.name.empty()) written_image["name"] = image.name;
    const int image_index = builder_.append("images", std::move(written_image));
    json sampler = {{"wrapS", texture.wrap_s}, {"wrapT", texture.wrap_t}};
    if (texture.mag_filter != 0) sampler["magFilter"] = texture.mag_filter;
    if (texture.min_filter != 0) sampler["minFilter"] = texture.min_filter;
    json written = {{"sampler", builder_.append("samplers", std::move(sampler))}};
    if (image.mime_type == "image/webp") {
      written["extensions"]["EXT_texture_webp"] = {{"source", image_index}};
      builder_.use_extension("EXT_texture_webp", true);
    } else {
      written["source"] = image_index;
    }
    const int out = builder_.append("textures", std::move(written));
    textures_[key] = out;
    return out;
  }

  int write_mesh(const ModelAsset& asset, const model::Mesh& mesh, bool skinned,
                 int first_material) {
    json primitives = json::array();
    const std::size_t targets = mesh.target_names.size();
    for (const model::Primitive& p : mesh.primitives) {
      std::vector<float> positions, normals, weights, uv0, uv1;
      // UV sets that some texture of the primitive's material reads.
      bool uses_uv[2] = {false, false};
      if (p.material >= 0) {
        const model::Material& m = asset.materials[static_cast<std::size_t>(p.material)];
        for (const model::TextureRef* ref : {&m.base_color_texture, &m.metallic_roughness_texture,
                                             &m.normal_texture, &m.occlusion_texture,
                                             &m.emissive_texture}) {
          if (ref->present()) uses_uv[ref->texcoord == 1 ? 1 : 0] = true;
        }
      }
      std::vector<std::uint16_t> joints;
      for (std::uint32_t v = 0; v < p.vertex_count; ++v) {
        const model::Vertex& vertex = asset.vertices[p.first_vertex + v];
        glm::vec3 normal = vertex.normal;
        normal = glm::length(normal) > 1e-12f ? glm::normalize(normal) : glm::vec3(0, 1, 0);
        positions.insert(positions.end(),
                         {vertex.position.x, vertex.position.y, vertex.position.z});
        normals.insert(normals.end(), {normal.x, normal.y, normal.z});
        if (uses_uv[0]) uv0.insert(uv0.end(), {vertex.uv0.x, vertex.uv0.y});
        if (uses_uv[1]) uv1.insert(uv1.end(), {vertex.uv1.x, vertex.uv1.y});
        if (skinned) {
          glm::vec4 w = vertex.weights;
          glm::uvec4 j = vertex.joints;
          // A joint without weight is written as joint 0 (validators flag unused duplicates).
          for (int c = 0; c < 4; ++c) {
            if (w[c] <= 0.0f) {
              w[c] = 0.0f;
              j[c] = 0;
            }
          }
          const float sum = w.x + w.y + w.z + w.w;
          if (sum <= 0.0f)
            w = glm::vec4(1, 0, 0, 0);
          else
            w /= sum;
          weights.insert(weights.end(), {w.x, w.y, w.z, w.w});
          for (int c = 0; c < 4; ++c) joints.push_back(static_cast<std::uint16_t>(j[c]));
        }
      }
      json attributes = {
          {"POSITION", builder_.add_floats(positions, "VEC3", BufferTarget::vertices, true)},
          {"NORMAL", builder_.add_floats(normals, "VEC3", BufferTarget::vertices, false)}};
      if (uses_uv[0]) attributes["TEXCOORD_0"] = builder_.add_floats(uv0, "VEC2", BufferTarget::vertices, false);
      if (uses_uv[1]) attributes["TEXCOORD_1"] = builder_.add_floats(uv1, "VEC2", BufferTarget::vertices, false);
      if (skinned) {
        attributes["JOINTS_0"] = builder_.add_joints(joints);
        attributes["WEIGHTS_0"] =
            builder_.add_floats(weights, "VEC4", BufferTarget::vertices, false);
      }
      std::vector<std::uint32_t> indices(asset.indices.begin() + p.first_index,
                                         asset.indices.begin() + p.first_index + p.index_count);
      json primitive = {
          {"attributes", attributes}, {"indices", builder_.add_indices(indices)}, {"mode", 4}};
      if (p.material >= 0) primitive["material"] = first_material + p.material;
      if (targets > 0) {
        json target_list = json::array();
        for (std::size_t k = 0; k < targets; ++k) {
          std::vector<float> dp, dn;
          for (std::uint32_t v = 0; v < p.vertex_count; ++v) {
            const model::MorphDelta& d =
                asset.morph_deltas[p.first_morph_delta + k * p.vertex_count + v];
            dp.insert(dp.end(), {d.position.x, d.position.y, d.position.z});
            dn.insert(dn.end(), {d.normal.x, d.normal.y, d.normal.z});
          }
          target_list.push_back(
              {{"POSITION", builder_.add_floats(dp, "VEC3", BufferTarget::vertices, true)},
               {"NORMAL", builder_.add_floats(dn, "VEC3", BufferTarget::vertices, false)}});
        }
        primitive["targets"] = std::move(target_list);
      }
      primitives.push_back(std::move(primitive));
    }
    json out = {{"primitives", std::move(primitives)}};
    if (!mesh.name.empty()) out["name"] = mesh.name;
    if (targets > 0) {
      out["weights"] = mesh.default_weights;
      out["extras"] = {{"targetNames", mesh.target_names}};
    }
    return builder_.append("meshes", std::move(out));
  }

  void write_instance(std::size_t i, const InstanceLabel& label, const InstanceSamples& s,
                      std::vector<int>& scene_roots) {
    const stage::PlacedModel& placed = stage_.placed(i);
    const ModelAsset& asset = *stage_.models()[placed.model];
    const WrittenModel& data = model_data(placed.model);
    json& nodes = builder_.document()["nodes"];
    if (!nodes.is_array()) nodes = json::array();
    const int root = static_cast<int>(nodes.size());
    const int base = root + 1;
    instance_root_.resize(std::max(instance_root_.size(), i + 1));
    instance_root_[i] = root;
    const int first_skin = builder_.document().contains("skins")
                               ? static_cast<int>(builder_.document()["skins"].size())
                               : 0;
    const std::size_t n = asset.nodes.size();

    json root_node = {{"name", label.name}};
    put_transform(root_node, s.roots.front());
    json children = json::array();
    std::vector<json> model_nodes(n);
    std::vector<bool> at_scene_root(n, false);
    for (std::size_t j = 0; j < n; ++j) {
      const model::Node& node = asset.nodes[j];
      json& out = model_nodes[j];
      out = json::object();
      if (!node.name.empty()) out["name"] = node.name;
      // A skinned mesh node's transform is ignored by glTF: it sits at the scene root.
      at_scene_root[j] = node.skin >= 0 && node.mesh >= 0 && node.children.empty();
      if (!at_scene_root[j]) put_transform(out, s.locals[j]);
      if (node.mesh >= 0) out["mesh"] = data.first_mesh + node.mesh;
      if (node.skin >= 0 && node.mesh >= 0) out["skin"] = first_skin + node.skin;
      if (!node.children.empty()) {
        json kids = json::array();
        for (int c : node.children) {
          if (!at_scene_root_of(asset, c)) kids.push_back(base + c);
        }
        if (!kids.empty()) out["children"] = std::move(kids);
      }
      if (node.mesh >= 0) {
        const auto weights = morph_slice(placed, node.mesh);
        if (weights.second > 0) {
          out["weights"] = std::vector<float>(s.weights.begin() + weights.first,
                                              s.weights.begin() + weights.first + weights.second);
        }
      }
    }
    for (std::size_t j = 0; j < n; ++j) {
      if (asset.nodes[j].parent >= 0) {
        if (at_scene_root[j]) scene_roots.push_back(base + static_cast<int>(j));
        continue;
      }
      if (at_scene_root[j])
        scene_roots.push_back(base + static_cast<int>(j));
      else
        children.push_back(base + static_cast<int>(j));
    }
    if (!children.empty()) root_node["children"] = std::move(children);
    nodes.push_back(std::move(root_node));
    scene_roots.push_back(root);
    for (json& node : model_nodes) nodes.push_back(std::move(node));

    for (const model::Skin& skin : asset.skins) {
      json joints = json::array();
      for (int joint : skin.joints) joints.push_back(base + joint);
      json out = {{"joints", std::move(joints)},
                  {"inverseBindMatrices",
                   data.inverse_binds[static_cast<std::size_t>(&skin - asset.skins.data())]}};
      if (!skin.name.empty()) out["name"] = skin.name;
      builder_.append("skins", std::move(out));
    }

    // Channels: the instance root, then every node that moves; morph weights on mesh nodes.
    const std::string clip = label.performer;
    const std::size_t frames = s.roots.size();
    add_transform_channels(
        clip, root, [&](std::size_t k) { return s.roots[k]; }, frames);
    for (std::size_t j = 0; j < n; ++j) {
      const int node = base + static_cast<int>(j);
      if (!at_scene_root[j]) {
        add_transform_channels(
            clip, node, [&](std::size_t k) { return s.locals[k * n + j]; }, frames);
      }
      if (asset.nodes[j].mesh >= 0) {
        const auto [first, width] = morph_slice(placed, asset.nodes[j].mesh);
        if (width > 0)
          add_weight_channel(clip, node, s.weights, placed.pose.morph_weights.size(), first, width,
                             frames);
      }
    }
  }

  static bool at_scene_root_of(const ModelAsset& asset, int node) {
    const model::Node& n = asset.nodes[static_cast<std::size_t>(node)];
    return n.skin >= 0 && n.mesh >= 0 && n.children.empty();
  }

  static std::pair<std::size_t, std::size_t> morph_slice(const stage::PlacedModel& placed,
                                                         int mesh) {
    const auto m = static_cast<std::size_t>(mesh);
    if (m >= placed.pose.first_morph_weight.size()) return {0, 0};
    const std::size_t first = placed.pose.first_morph_weight[m];
    const std::size_t end = m + 1 < placed.pose.first_morph_weight.size()
                                ? placed.pose.first_morph_weight[m + 1]
                                : placed.pose.morph_weights.size();
    return {first, end - first};
  }

  template <typename TransformAt>
  void add_transform_channels(const std::string& clip, int node, TransformAt at,
                              std::size_t frames) {
    std::vector<glm::vec3> translation(frames), scale(frames);
    std::vector<glm::quat> rotation(frames);
    for (std::size_t k = 0; k < frames; ++k) {
      const NodeTransform t = at(k);
      translation[k] = t.translation;
      scale[k] = t.scale;
      rotation[k] = t.rotation;
      // One hemisphere, so that glTF's interpolation between keys takes the short way.
      if (k > 0 && glm::dot(rotation[k - 1], rotation[k]) < 0.0f) rotation[k] = -rotation[k];
    }
    if (!constant_vec3(translation, tolerances_.translation_m)) {
      const auto keys = reduce_vec3(translation, tolerances_.translation_m, tolerances_.max_span);
      add_channel(
          clip, node, "translation", keys,
          [&](std::uint32_t k, std::vector<float>& out) {
            out.insert(out.end(), {translation[k].x, translation[k].y, translation[k].z});
          },
          "VEC3", frames);
    }
    if (!constant_rotation(rotation, tolerances_.rotation_rad)) {
      const auto keys = reduce_rotation(rotation, tolerances_.rotation_rad, tolerances_.max_span);
      add_channel(
          clip, node, "rotation", keys,
          [&](std::uint32_t k, std::vector<float>& out) {
            out.insert(out.end(), {rotation[k].x, rotation[k].y, rotation[k].z, rotation[k].w});
          },
          "VEC4", frames);
    }
    if (!constant_vec3(scale, tolerances_.scale)) {
      const auto keys = reduce_vec3(scale, tolerances_.scale, tolerances_.max_span);
      add_channel(
          clip, node, "scale", keys,
          [&](std::uint32_t k, std::vector<float>& out) {
            out.insert(out.end(), {scale[k].x, scale[k].y, scale[k].z});
          },
          "VEC3", frames);
    }
  }

  void add_weight_channel(const std::string& clip, int node, const std::vector<float>& all,
                          std::size_t stride, std::size_t first, std::size_t width,
                          std::size_t frames) {
    std::vector<float> samples;
    samples.reserve(frames * width);
    for (std::size_t k = 0; k < frames; ++k) {
      const auto from = all.begin() + static_cast<std::ptrdiff_t>(k * stride + first);
      samples.insert(samples.end(), from, from + static_cast<std::ptrdiff_t>(width));
    }
    if (constant_weights(samples, width, tolerances_.weight)) return;
    const auto keys = reduce_weights(samples, width, tolerances_.weight, tolerances_.max_span);
    add_channel(
        clip, node, "weights", keys,
        [&](std::uint32_t k, std::vector<float>& out) {
          const auto from = samples.begin() + static_cast<std::ptrdiff_t>(k * width);
          out.insert(out.end(), from, from + static_cast<std::ptrdiff_t>(width));
        },
        "SCALAR", frames);
  }

  template <typename Values>
  void add_channel(const std::string& clip, int node, const char* path,
                   const std::vector<std::uint32_t>& keys, Values values, const char* type,
                   std::size_t frames) {
    std::vector<float> output;
    for (std::uint32_t k : keys) values(k, output);
    Channel c;
    c.clip = clip;
    c.node = node;
    c.path = path;
    c.input = time_accessor(keys);
    c.output = builder_.add_floats(output, type, BufferTarget::none, false);
    c.keys = keys.size();
    samples_ += frames;
    channels_.push_back(c);
  }

  int time_accessor(const std::vector<std::uint32_t>& keys) {
    auto found = times_.find(keys);
    if (found != times_.end()) return found->second;
    std::vector<float> seconds;
    seconds.reserve(keys.size());
    for (std::uint32_t k : keys) {
      seconds.push_back(static_cast<float>(static_cast<double>(k) / range_.fps));
    }
    const int accessor = builder_.add_floats(seconds, "SCALAR", BufferTarget::none, true);
    times_.emplace(keys, accessor);
    return accessor;
  }

  ClipSummary write_animation(const std::string& name, const std::vector<const Channel*>& list) {
    json samplers = json::array();
    json channels = json::array();
    ClipSummary summary;
    summary.name = name;
    for (const Channel* c : list) {
      channels.push_back(
          {{"sampler", samplers.size()}, {"target", {{"node", c->node}, {"path", c->path}}}});
      samplers.push_back({{"input", c->input}, {"output", c->output}, {"interpolation", "LINEAR"}});
      summary.keys += c->keys;
    }
    summary.channels = list.size();
    builder_.append(
        "animations",
        {{"name", name}, {"samplers", std::move(samplers)}, {"channels", std::move(channels)}});
    return summary;
  }

  const stage::Stage& stage_;
  ExportRange range_;
  KeyTolerances tolerances_;
  GlbBuilder builder_;
  std::vector<WrittenModel> written_;
  std::vector<int> instance_root_;  // each instance's root node in the file
  std::map<std::pair<const ModelAsset*, int>, int> textures_;  // (model, texture) -> written
  std::vector<Channel> channels_;
  std::map<std::vector<std::uint32_t>, int> times_;
  std::size_t samples_ = 0;
};

}  // namespace

Result<ExportSummary> export_performance(const stage::Stage& stage, const ExportRange& range,
                                         const KeyTolerances& tolerances) {
  if (range.frame_count <= 0) return Error{stage.scene().source + ": nothing to export"};
  if (range.fps <= 0) return Error{stage.scene().source + ": fps must be positive"};
  return Writer(stage, range, tolerances).run();
}

}  // namespace tutti::gltf_export
