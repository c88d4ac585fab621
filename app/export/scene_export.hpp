// SPDX-License-Identifier: MIT
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
#include <tutti/performance/model_names.hpp>
#include <tutti/stage/stage.hpp>

namespace tutti::gltf_export {

struct ExportRange {
  int fps = 30;
  std::int64_t first_frame = 0;  // frame k shows offline_frame_time(stage.start_s(), fps, k)
  std::int64_t frame_count = 0;
};

// The names of the nodes and clips (tutti::performance's names of the models and performers).
using performance::clip_names;
using performance::InstanceLabel;
using performance::label_instances;
using performance::whole_scene_clip_name;

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

// Errors: an empty range. Poses every exported frame in a context of its own
// (Stage::make_context): the stage itself is left as it was.
Result<ExportSummary> export_performance(const stage::Stage& stage, const ExportRange& range,
                                         const KeyTolerances& tolerances = {});

}  // namespace tutti::gltf_export
