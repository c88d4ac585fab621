// SPDX-License-Identifier: MIT
#pragma once
// The node tree of a glTF file: matrices decomposed into TRS, and an order in which parents come
// before their children. Internal to tutti_model; errors are reasons without the file name.

#include <tiny_gltf.h>

#include <span>
#include <string>
#include <vector>

#include <tutti/core/result.hpp>
#include <tutti/model/model_asset.hpp>

namespace tutti::model::detail {

// "node 3" or `node 3 "wrist"`.
std::string describe_node(const tinygltf::Model& model, std::size_t index);

// A glTF `matrix` (16 numbers, column-major) as translation, rotation and scale. Refused: a
// non-finite number, a last row other than (0 0 0 1), and any matrix T * R * S cannot rebuild
// (shear, non-uniform scale along rotated axes).
Result<NodeTransform> decompose_matrix(std::span<const double> matrix);

// A node's TRS (or its decomposed matrix); refused: wrong array lengths, non-finite numbers, a
// zero rotation quaternion, both a matrix and TRS. Rotations are normalised.
Result<NodeTransform> node_transform(const tinygltf::Node& node);

struct NodeOrder {
  std::vector<int> parent;     // per file node: its parent's file index, -1 for none
  std::vector<int> file_node;  // per new index: the file node
  std::vector<int> new_index;  // per file node: its new index
};

// Parents before children, otherwise the file's order (the smallest ready index first, so a
// file that is already in order keeps its indices). Refused: a child index out of range, a node
// that is its own child, a node with two parents (or listed twice), a cycle.
Result<NodeOrder> order_nodes(const tinygltf::Model& model);

}  // namespace tutti::model::detail
