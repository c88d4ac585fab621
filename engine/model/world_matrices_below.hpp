// SPDX-License-Identifier: MIT
#pragma once
// World matrices of one node and everything below it, when only that part of a pose changed:
// an arm set by IK moves the arm, the hand and its fingers, and nothing else. The same products
// in the same order as compute_world_matrices (model_asset.hpp), so the result is bit for bit
// what a whole pass gives; a whole pass over a 100-node body costs several times more.

#include <span>

#include <glm/glm.hpp>

#include <tutti/model/model_asset.hpp>

namespace tutti::model {

// `world` must hold the current pose's matrices for every node outside node's subtree (above
// all, its parent's); node's and its descendants' are recomputed from `pose`. A node outside
// the model does nothing. Allocation-free; nodes are found by their parent links.
void update_world_matrices_below(const ModelAsset& asset, const ModelPose& pose,
                                 const glm::mat4& root_world, int node, std::span<glm::mat4> world);

}  // namespace tutti::model
