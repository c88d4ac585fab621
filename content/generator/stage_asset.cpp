// SPDX-License-Identifier: MIT
#include <tutti/generator/stage_asset.hpp>

#include <cmath>

#include <tutti/generator/gltf_builder.hpp>

namespace tutti::content_generator {
tinygltf::Model build_stage(const StageDimensions& dims) {
  ModelBuilder builder;
  const int oak = builder.add_material({"stage_oak", {0.32, 0.17, 0.07, 1.0}, 0.0, 0.55});
  const int oak_dark = builder.add_material({"stage_oak_dark", {0.24, 0.12, 0.05, 1.0}, 0.0, 0.6});
  const int skirt_cloth =
      builder.add_material({"stage_skirt", {0.015, 0.015, 0.018, 1.0}, 0.0, 0.95});

  const double half_w = dims.width_mm / 2;
  const double half_d = dims.depth_mm / 2;
  const double inner_w = half_w - dims.edge_width_mm;
  const double inner_d = half_d - dims.edge_width_mm;
  const double board_mm = 25.0;  // plank thickness, below the top
  // Planks run front to back (along Z); every other one slightly darker so the floor reads as
  // boards. Two meshes, not one per plank: a plank is a box inside one of them.
  MeshData light;
  MeshData dark;
  const int planks = static_cast<int>(std::ceil(2 * inner_w / dims.plank_width_mm));
  for (int i = 0; i < planks; ++i) {
    const double x0 = -inner_w + i * dims.plank_width_mm + dims.plank_gap_mm / 2;
    const double x1 =
        std::min(-inner_w + (i + 1) * dims.plank_width_mm, inner_w) - dims.plank_gap_mm / 2;
    if (x1 <= x0) continue;
    add_box(i % 2 == 0 ? light : dark, {m(x0), m(-board_mm), m(-inner_d)},
            {m(x1), 0.0f, m(inner_d)});
  }
  // The deck under the planks fills the gaps (seen as dark lines) and carries the skirt.
  MeshData deck;
  add_box(deck, {m(-half_w), m(-dims.platform_height_mm), m(-half_d)},
          {m(half_w), m(-board_mm), m(half_d)});
  // The nosing: a strip around the edge, edge_height_mm above the floor.
  MeshData edge;
  const float top = m(dims.edge_height_mm);
  add_box(edge, {m(-half_w), m(-board_mm), m(inner_d)}, {m(half_w), top, m(half_d)});    // front
  add_box(edge, {m(-half_w), m(-board_mm), m(-half_d)}, {m(half_w), top, m(-inner_d)});  // back
  add_box(edge, {m(-half_w), m(-board_mm), m(-inner_d)}, {m(-inner_w), top, m(inner_d)});
  add_box(edge, {m(inner_w), m(-board_mm), m(-inner_d)}, {m(half_w), top, m(inner_d)});

  const int stage = builder.add_node("stage");
  builder.add_root(stage);
  const int floor = builder.add_node("floor", builder.add_mesh("stage_planks", light, oak));
  builder.add_child(stage, floor);
  builder.add_child(stage,
                    builder.add_node("floor_alternate",
                                     builder.add_mesh("stage_planks_alternate", dark, oak_dark)));
  builder.add_child(stage,
                    builder.add_node("edge", builder.add_mesh("stage_edge", edge, oak_dark)));
  builder.add_child(stage,
                    builder.add_node("skirt", builder.add_mesh("stage_skirt", deck, skirt_cloth)));
  return builder.finish();
}

}  // namespace tutti::content_generator
