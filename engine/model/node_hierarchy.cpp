// SPDX-License-Identifier: MIT
#include <tutti/model/node_hierarchy.hpp>

#include <cmath>
#include <functional>
#include <glm/gtc/quaternion.hpp>
#include <queue>

namespace tutti::model::detail {
namespace {

bool all_finite(std::span<const double> values) {
  for (const double v : values) {
    if (!std::isfinite(v)) return false;
  }
  return true;
}

// Any unit vector perpendicular to unit `axis`.
glm::dvec3 perpendicular(const glm::dvec3& axis) {
  const glm::dvec3 helper =
      std::abs(axis.x) < 0.9 ? glm::dvec3(1.0, 0.0, 0.0) : glm::dvec3(0.0, 1.0, 0.0);
  return glm::normalize(glm::cross(axis, helper));
}

}  // namespace

std::string describe_node(const tinygltf::Model& model, std::size_t index) {
  std::string text = "node " + std::to_string(index);
  if (index < model.nodes.size() && !model.nodes[index].name.empty()) {
    text += " \"" + model.nodes[index].name + "\"";
  }
  return text;
}

Result<NodeTransform> decompose_matrix(std::span<const double> m) {
  if (m.size() != 16) return Error{"matrix has " + std::to_string(m.size()) + " numbers, not 16"};
  if (!all_finite(m)) return Error{"matrix has a non-finite number"};
  constexpr double kTolerance = 1e-5;
  if (std::abs(m[3]) > kTolerance || std::abs(m[7]) > kTolerance || std::abs(m[11]) > kTolerance ||
      std::abs(m[15] - 1.0) > kTolerance) {
    return Error{"matrix is not affine (last row is not 0 0 0 1)"};
  }
  glm::dvec3 column[3];
  double scale[3];
  for (int c = 0; c < 3; ++c) {
    const auto base = static_cast<std::size_t>(4 * c);
    column[c] = {m[base], m[base + 1], m[base + 2]};
    scale[c] = glm::length(column[c]);
  }
  double largest = std::max({scale[0], scale[1], scale[2]});
  const double tiny = 1e-12 * std::max(largest, 1.0);
  // Rotation axes: the normalised columns; a zero-scale column takes the direction that makes a
  // right-handed basis with the others.
  glm::dvec3 axis[3];
  int zero_count = 0;
  for (int c = 0; c < 3; ++c) {
    if (scale[c] > tiny) {
      axis[c] = column[c] / scale[c];
    } else {
      ++zero_count;
      scale[c] = 0.0;
    }
  }
  if (zero_count == 3) {
    for (int c = 0; c < 3; ++c) axis[c] = glm::dvec3(0.0);
    axis[0].x = axis[1].y = axis[2].z = 1.0;
  } else if (zero_count == 2) {
    const int c = scale[0] > 0 ? 0 : (scale[1] > 0 ? 1 : 2);
    axis[(c + 1) % 3] = perpendicular(axis[c]);
    axis[(c + 2) % 3] = glm::cross(axis[c], axis[(c + 1) % 3]);
  } else if (zero_count == 1) {
    const int c = scale[0] == 0 ? 0 : (scale[1] == 0 ? 1 : 2);
    axis[c] = glm::cross(axis[(c + 1) % 3], axis[(c + 2) % 3]);
    const double length = glm::length(axis[c]);
    if (length < 1e-6) return Error{"matrix has shear (two parallel axes)"};
    axis[c] /= length;
  } else if (glm::dot(glm::cross(axis[0], axis[1]), axis[2]) < 0.0) {
    // A mirror: one negative scale (on x) and a proper rotation.
    scale[0] = -scale[0];
    axis[0] = -axis[0];
  }
  const glm::dmat3 rotation(axis[0], axis[1], axis[2]);
  glm::dquat q = glm::quat_cast(rotation);
  q = glm::normalize(q);

  NodeTransform out;
  out.translation = glm::vec3(glm::dvec3(m[12], m[13], m[14]));
  out.rotation = glm::quat(q);
  out.scale = glm::vec3(static_cast<float>(scale[0]), static_cast<float>(scale[1]),
                        static_cast<float>(scale[2]));

  // T * R * S must give the matrix back; otherwise it had shear.
  const glm::dmat3 rebuilt =
      glm::mat3_cast(q) * glm::dmat3(glm::dvec3(scale[0], 0, 0), glm::dvec3(0, scale[1], 0),
                                     glm::dvec3(0, 0, scale[2]));
  largest = std::max(largest, 1.0);
  for (int c = 0; c < 3; ++c) {
    for (int r = 0; r < 3; ++r) {
      if (std::abs(rebuilt[c][r] - column[c][r]) > 1e-4 * largest) {
        return Error{"matrix has shear (not a translation, rotation and scale)"};
      }
    }
  }
  return out;
}

Result<NodeTransform> node_transform(const tinygltf::Node& node) {
  const bool has_trs = !node.translation.empty() || !node.rotation.empty() || !node.scale.empty();
  if (!node.matrix.empty()) {
    if (has_trs) return Error{"has both a matrix and translation/rotation/scale"};
    return decompose_matrix(node.matrix);
  }
  NodeTransform out;
  if (!node.translation.empty()) {
    if (node.translation.size() != 3 || !all_finite(node.translation)) {
      return Error{"translation is not 3 finite numbers"};
    }
    out.translation =
        glm::vec3(glm::dvec3(node.translation[0], node.translation[1], node.translation[2]));
  }
  if (!node.rotation.empty()) {
    if (node.rotation.size() != 4 || !all_finite(node.rotation)) {
      return Error{"rotation is not 4 finite numbers"};
    }
    // glTF stores (x, y, z, w); glm's constructor takes (w, x, y, z).
    const glm::dquat q(node.rotation[3], node.rotation[0], node.rotation[1], node.rotation[2]);
    const double length = glm::length(q);
    if (!(length > 1e-6) || !std::isfinite(length)) return Error{"rotation quaternion is zero"};
    out.rotation = glm::quat(q / length);
  }
  if (!node.scale.empty()) {
    if (node.scale.size() != 3 || !all_finite(node.scale)) {
      return Error{"scale is not 3 finite numbers"};
    }
    out.scale = glm::vec3(glm::dvec3(node.scale[0], node.scale[1], node.scale[2]));
  }
  return out;
}

Result<NodeOrder> order_nodes(const tinygltf::Model& model) {
  const std::size_t n = model.nodes.size();
  NodeOrder order;
  order.parent.assign(n, -1);
  for (std::size_t i = 0; i < n; ++i) {
    for (const int child : model.nodes[i].children) {
      if (child < 0 || static_cast<std::size_t>(child) >= n) {
        return Error{describe_node(model, i) + ": child " + std::to_string(child) +
                     " does not exist (the file has " + std::to_string(n) + " nodes)"};
      }
      const auto c = static_cast<std::size_t>(child);
      if (c == i) return Error{describe_node(model, i) + " is its own child"};
      if (order.parent[c] == static_cast<int>(i)) {
        return Error{describe_node(model, c) + " is listed twice as a child of " +
                     describe_node(model, i)};
      }
      if (order.parent[c] != -1) {
        return Error{describe_node(model, c) + " has two parents (" +
                     describe_node(model, static_cast<std::size_t>(order.parent[c])) + " and " +
                     describe_node(model, i) + ")"};
      }
      order.parent[c] = static_cast<int>(i);
    }
  }
  // Kahn's algorithm with the smallest ready node first: with one parent per node, what is never
  // reached from a parentless node is on (or below) a cycle.
  std::priority_queue<int, std::vector<int>, std::greater<>> ready;
  for (std::size_t i = 0; i < n; ++i) {
    if (order.parent[i] == -1) ready.push(static_cast<int>(i));
  }
  order.new_index.assign(n, -1);
  order.file_node.reserve(n);
  while (!ready.empty()) {
    const int node = ready.top();
    ready.pop();
    order.new_index[static_cast<std::size_t>(node)] = static_cast<int>(order.file_node.size());
    order.file_node.push_back(node);
    for (const int child : model.nodes[static_cast<std::size_t>(node)].children) ready.push(child);
  }
  if (order.file_node.size() != n) {
    for (std::size_t i = 0; i < n; ++i) {
      if (order.new_index[i] == -1) {
        // Walk up until a node repeats: that one is on the cycle.
        std::vector<bool> seen(n, false);
        std::size_t at = i;
        while (!seen[at]) {
          seen[at] = true;
          at = static_cast<std::size_t>(order.parent[at]);
        }
        return Error{describe_node(model, at) + " is its own ancestor (a cycle in the node tree)"};
      }
    }
  }
  return order;
}

}  // namespace tutti::model::detail
