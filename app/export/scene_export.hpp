#pragma once
// A staged scene's performance as one glTF 2.0 binary: every placed model (characters, hands,
// piano, instruments, props) with its meshes, materials, skins and morph targets, and the
// performance baked over a range of frames as glTF animation — node translations, rotations and
// scales (joints, keys, valves, the slide, body motion, the instrument hanging from the lips) and
// morph weights (the mouth). One animation per performer, named after them ("pianist" for the
// pianist: body, hands and piano keys), plus one for the whole scene.
//
// Sampling: frame k is posed at the render's time for it (audio_sync::offline_frame_time), so an
// exported clip lines up with `tutti render` frame for frame; the clip's time 0 is the first
// exported frame. Keys are reduced with KeyTolerances (keyframe_reduction.hpp). Structure:
// each instance is a root node named after it with the model's nodes below; a skinned mesh node
// is a scene root without a transform (glTF ignores its transform; validators and importers
// expect it at the root). A user's model (mapping file) exports with its own nodes and names.
//
// Deterministic: the same stage, range and tolerances give the same bytes.

#include <cstdint>
#include <string>
#include <vector>

#include <tutti/core/result.hpp>
#include <tutti/export/keyframe_reduction.hpp>
#include <tutti/stage/stage.hpp>

namespace tutti::gltf_export {

struct ExportRange {
  int fps = 30;
  std::int64_t first_frame = 0;  // frame k shows offline_frame_time(stage.start_s(), fps, k)
  std::int64_t frame_count = 0;
};

// One placed model as it is exported: its node's name and the clip it animates in ("" for a
// prop that belongs to no performer: it is only in the whole-scene clip).
struct InstanceLabel {
  std::string name;  // unique in the file: "Anna", "Anna trumpet", "piano", "chair 2", ...
  std::string performer;
};
// In Stage::instances() order.
std::vector<InstanceLabel> label_instances(const stage::Stage& stage);

struct ClipSummary {
  std::string name;
  std::size_t channels = 0;
  std::size_t keys = 0;  // kept keyframes over its channels
};

struct ExportSummary {
  std::vector<std::uint8_t> glb;
  std::vector<ClipSummary> clips;  // the performers' in scene order, then the whole scene's
  std::size_t nodes = 0, meshes = 0, skins = 0;
  std::size_t samples = 0;  // channel samples before reduction (whole-scene clip)
  std::size_t keys = 0;     // after (whole-scene clip)
  double duration_s = 0.0;  // the clip length: (frame_count - 1) / fps
};

// Errors: an empty range. Evaluates the stage at every exported frame (the stage is left posed at
// the last one).
Result<ExportSummary> export_performance(stage::Stage& stage, const ExportRange& range,
                                         const KeyTolerances& tolerances = {});

// Each performer's clip name, in Stage::performers() order: the performer's name, followed by
// " (<family>)" when an earlier performer has the same name ("pianist (piano)" after a brass
// player called "pianist").
std::vector<std::string> clip_names(const stage::Stage& stage);
// The name of the whole-scene clip: "scene", or "scene (all)" when a performer is called "scene".
std::string whole_scene_clip_name(const stage::Stage& stage);

}  // namespace tutti::gltf_export
