// SPDX-License-Identifier: MIT
// A host that is not tutti's renderer: it opens a scene with tutti::performance alone (no Vulkan),
// samples one performer's body at a fixed frame rate and writes it as BVH motion capture, the
// skeleton named and shaped as the model's own nodes. Blender, MotionBuilder and most engines
// import BVH. docs/embedding.md walks through it.
//
//   tutti_write_bvh SCENE PERFORMER OUT.bvh [SECONDS] [FPS]
//
// Exit 0: written; 2: bad input (one line on stderr).
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <string>
#include <vector>

#include <tutti/performance/performance.hpp>

namespace {

using tutti::performance::Performance;
using tutti::performance::Sample;
using tutti::performance::Trs;

constexpr double kPi = 3.14159265358979323846;

// A unit quaternion (x, y, z, w) as BVH's Z, X, Y rotations in degrees (R = Rz Rx Ry).
void euler_zxy(const std::array<float, 4>& q, double out[3]) {
  const double x = q[0], y = q[1], z = q[2], w = q[3];
  const double m21 = 2 * (y * z + w * x);  // row 2, column 1 of the rotation matrix
  const double rx = std::asin(std::fmax(-1.0, std::fmin(1.0, m21)));
  const double m01 = 2 * (x * y - w * z), m11 = 1 - 2 * (x * x + z * z);
  const double m20 = 2 * (x * z - w * y), m22 = 1 - 2 * (x * x + y * y);
  const double rz = std::atan2(-m01, m11);
  const double ry = std::atan2(-m20, m22);
  out[0] = rz * 180.0 / kPi;
  out[1] = rx * 180.0 / kPi;
  out[2] = ry * 180.0 / kPi;
}

struct Skeleton {
  const tutti::performance::ModelInfo* model = nullptr;
  std::vector<std::vector<int>> children;
  std::vector<int> order;  // nodes in the order the hierarchy lists them (depth first)
};

void write_joint(std::ofstream& out, const Skeleton& s, const Sample& rest, std::size_t model,
                 int node, int depth, std::vector<int>& order) {
  const std::string indent(static_cast<std::size_t>(depth) * 2, ' ');
  const Trs& t = rest.models[model].local[static_cast<std::size_t>(node)];
  out << indent << (depth == 0 ? "ROOT " : "JOINT ") << s.model->nodes[static_cast<std::size_t>(node)]
      << "\n" << indent << "{\n";
  // Centimetres, as BVH tools expect.
  out << indent << "  OFFSET " << t.translation[0] * 100 << " " << t.translation[1] * 100 << " "
      << t.translation[2] * 100 << "\n";
  out << indent << "  CHANNELS 6 Xposition Yposition Zposition Zrotation Xrotation Yrotation\n";
  order.push_back(node);
  const auto& kids = s.children[static_cast<std::size_t>(node)];
  if (kids.empty()) {
    out << indent << "  End Site\n" << indent << "  {\n" << indent << "    OFFSET 0 0 0\n"
        << indent << "  }\n";
  }
  for (int child : kids) write_joint(out, s, rest, model, child, depth + 1, order);
  out << indent << "}\n";
}

}  // namespace

int main(int argc, char** argv) {
  if (argc < 4) {
    std::fprintf(stderr, "usage: tutti_write_bvh SCENE PERFORMER OUT.bvh [SECONDS] [FPS]\n");
    return 2;
  }
  const double seconds = argc > 4 ? std::atof(argv[4]) : 10.0;
  const int fps = argc > 5 ? std::atoi(argv[5]) : 30;
  if (!(seconds > 0) || fps < 1 || fps > 240) {
    std::fprintf(stderr, "error: SECONDS must be > 0 and FPS 1..240\n");
    return 2;
  }
  // 1. The scene, staged once: music, models, every performer's plan. No GPU, no window.
  auto performance = Performance::open(argv[1]);
  if (!performance) {
    std::fprintf(stderr, "error: %s\n", performance.error().message.c_str());
    return 2;
  }
  Performance& p = **performance;
  // 2. The performer's body: the model named after them, its nodes as the skeleton.
  std::size_t model = p.models().size();
  for (std::size_t m = 0; m < p.models().size(); ++m) {
    if (p.models()[m].name == argv[2] && p.models()[m].performer >= 0) model = m;
  }
  if (model == p.models().size()) {
    std::fprintf(stderr, "error: %s: no performer \"%s\"\n", argv[1], argv[2]);
    return 2;
  }
  Skeleton skeleton;
  skeleton.model = &p.models()[model];
  skeleton.children.resize(skeleton.model->nodes.size());
  std::vector<int> roots;
  for (std::size_t n = 0; n < skeleton.model->parents.size(); ++n) {
    const int parent = skeleton.model->parents[n];
    (parent < 0 ? roots : skeleton.children[static_cast<std::size_t>(parent)])
        .push_back(static_cast<int>(n));
  }
  // 3. The hierarchy from the pose at the start, then one frame per sample(t).
  Sample sample;
  p.sample(p.start_s(), sample);
  std::ofstream out(argv[3]);
  out << "HIERARCHY\n";
  std::vector<int> order;
  for (int root : roots) write_joint(out, skeleton, sample, model, root, 0, order);
  const int frames = static_cast<int>(std::floor(seconds * fps));
  out << "MOTION\nFrames: " << frames << "\nFrame Time: " << 1.0 / fps << "\n";
  for (int k = 0; k < frames; ++k) {
    p.sample(p.start_s() + static_cast<double>(k) / fps, sample);
    const auto& locals = sample.models[model].local;
    for (std::size_t i = 0; i < order.size(); ++i) {
      const Trs& t = locals[static_cast<std::size_t>(order[i])];
      double euler[3];
      euler_zxy(t.rotation, euler);
      out << (i == 0 ? "" : " ") << t.translation[0] * 100 << " " << t.translation[1] * 100 << " "
          << t.translation[2] * 100 << " " << euler[0] << " " << euler[1] << " " << euler[2];
    }
    out << "\n";
  }
  out.close();
  if (!out) {
    std::fprintf(stderr, "error: %s: cannot write\n", argv[3]);
    return 2;
  }
  std::printf("bvh: %s, %zu joints, %d frames at %d fps from %s\n", argv[3], order.size(), frames,
              fps, argv[1]);
  return 0;
}
