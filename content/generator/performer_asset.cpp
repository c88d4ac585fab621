// SPDX-License-Identifier: MIT
#include <tutti/generator/performer_asset.hpp>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <functional>
#include <map>
#include <numbers>
#include <string>
#include <vector>

#include <tutti/generator/gltf_builder.hpp>
#include <tutti/generator/hand_asset.hpp>

namespace tutti::content_generator {
namespace {

DVec3 operator+(DVec3 a, DVec3 b) { return {a[0] + b[0], a[1] + b[1], a[2] + b[2]}; }
DVec3 operator-(DVec3 a, DVec3 b) { return {a[0] - b[0], a[1] - b[1], a[2] - b[2]}; }
DVec3 operator*(double s, DVec3 a) { return {s * a[0], s * a[1], s * a[2]}; }
double length(DVec3 a) { return std::sqrt(dot(a, a)); }
Vec3 f3(DVec3 a) {
  return {static_cast<float>(a[0]), static_cast<float>(a[1]), static_cast<float>(a[2])};
}
float f(double v) { return static_cast<float>(v); }
double smooth(double x) {
  const double t = std::clamp(x, 0.0, 1.0);
  return t * t * (3.0 - 2.0 * t);
}

// Up to four joints and their weights for one vertex.
struct Influence {
  std::array<int, 4> joint{-1, -1, -1, -1};
  std::array<double, 4> weight{};
};

Influence rigid(int joint) { return {{joint, -1, -1, -1}, {1.0, 0.0, 0.0, 0.0}}; }

// Weights every vertex from `first` on by `influence(bind-pose position)`, normalised to 1.
void weight_with(MeshData& mesh, std::size_t first,
                 const std::function<Influence(DVec3)>& influence) {
  for (std::size_t v = first; v < mesh.vertex_count(); ++v) {
    const Influence in =
        influence({mesh.positions[3 * v], mesh.positions[3 * v + 1], mesh.positions[3 * v + 2]});
    double sum = 0.0;
    for (std::size_t k = 0; k < 4; ++k) {
      if (in.joint[k] >= 0) sum += in.weight[k];
    }
    for (std::size_t k = 0; k < 4; ++k) {
      const bool used = in.joint[k] >= 0 && sum > 0.0;
      mesh.joints.push_back(static_cast<std::uint16_t>(used ? in.joint[k] : 0));
      mesh.weights.push_back(used ? static_cast<float>(in.weight[k] / sum) : 0.0f);
    }
  }
}

// A limb segment from joint a to joint b (bone `self`): vertices within `band` metres of a
// share up to half their weight with `parent`, within `band` of b with `child` (-1: none), so
// the skin bends smoothly; at the joint itself the two bones weigh half each.
Influence limb_influence(DVec3 p, DVec3 a, DVec3 b, int parent, int self, int child, double band) {
  const DVec3 axis = b - a;
  const double len = length(axis);
  const double t = dot(p - a, axis) / len;  // metres along the segment
  const double to_parent = parent >= 0 ? 0.5 * (1.0 - smooth(t / band)) : 0.0;
  const double to_child = child >= 0 ? 0.5 * smooth((t - (len - band)) / band) : 0.0;
  return {{self, parent, child, -1}, {1.0 - to_parent - to_child, to_parent, to_child, 0.0}};
}

// A tapered tube with rounded ends and `rings` rings along it (so it bends smoothly when
// skinned), radius ra at a and rb at b (metres).
void add_limb(MeshData& mesh, DVec3 a, DVec3 b, double ra, double rb, int rings = 8,
              int segments = 16) {
  Tube tube;
  for (int i = 0; i < rings; ++i) {
    const double u = static_cast<double>(i) / (rings - 1);
    tube.centres.push_back(f3(a + u * (b - a)));
    tube.radii.push_back(f(ra + u * (rb - ra)));
  }
  tube.segments = segments;
  tube.start = Tube::End::rounded;
  tube.end = Tube::End::rounded;
  add_tube(mesh, tube);
}

// Scales the vertices from `first` on about `centre` (normals by the inverse, renormalised).
void scale_about(MeshData& mesh, std::size_t first, DVec3 centre, DVec3 scale) {
  for (std::size_t v = first; v < mesh.vertex_count(); ++v) {
    double n2 = 0.0;
    for (std::size_t k = 0; k < 3; ++k) {
      float& p = mesh.positions[3 * v + k];
      p = f(centre[k] + (p - centre[k]) * scale[k]);
      float& n = mesh.normals[3 * v + k];
      n = f(n / scale[k]);
      n2 += static_cast<double>(n) * n;
    }
    const double inv = 1.0 / std::sqrt(n2);
    for (std::size_t k = 0; k < 3; ++k) mesh.normals[3 * v + k] *= f(inv);
  }
}

// Appends the triangles of `part` whose centroid passes `keep`, and only the vertices they use.
void append_where(MeshData& mesh, const MeshData& part, const std::function<bool(DVec3)>& keep) {
  std::map<std::uint16_t, std::uint16_t> remap;
  for (std::size_t t = 0; t + 2 < part.indices.size(); t += 3) {
    DVec3 centroid{0, 0, 0};
    for (std::size_t k = 0; k < 3; ++k) {
      const std::size_t i = part.indices[t + k];
      centroid = centroid + (1.0 / 3.0) * DVec3{part.positions[3 * i], part.positions[3 * i + 1],
                                                part.positions[3 * i + 2]};
    }
    if (!keep(centroid)) continue;
    for (std::size_t k = 0; k < 3; ++k) {
      const std::uint16_t i = part.indices[t + k];
      auto [at, inserted] = remap.emplace(i, static_cast<std::uint16_t>(mesh.vertex_count()));
      if (inserted) {
        for (std::size_t c = 0; c < 3; ++c) {
          mesh.positions.push_back(part.positions[3 * i + c]);
          mesh.normals.push_back(part.normals[3 * i + c]);
        }
      }
      mesh.indices.push_back(at->second);
    }
  }
}

// The unit quaternion (x, y, z, w) of the rotation part of a column-major matrix (Shepperd).
Quat rotation_quat(const Mat4& m) {
  const double m00 = m[0], m11 = m[5], m22 = m[10];
  const double m01 = m[4], m02 = m[8], m10 = m[1], m12 = m[9], m20 = m[2], m21 = m[6];
  const double trace = m00 + m11 + m22;
  Quat q{0, 0, 0, 1};
  if (trace > 0) {
    const double s = std::sqrt(trace + 1.0) * 2;
    q = {(m21 - m12) / s, (m02 - m20) / s, (m10 - m01) / s, 0.25 * s};
  } else if (m00 > m11 && m00 > m22) {
    const double s = std::sqrt(1.0 + m00 - m11 - m22) * 2;
    q = {0.25 * s, (m01 + m10) / s, (m02 + m20) / s, (m21 - m12) / s};
  } else if (m11 > m22) {
    const double s = std::sqrt(1.0 + m11 - m00 - m22) * 2;
    q = {(m01 + m10) / s, 0.25 * s, (m12 + m21) / s, (m02 - m20) / s};
  } else {
    const double s = std::sqrt(1.0 + m22 - m00 - m11) * 2;
    q = {(m02 + m20) / s, (m12 + m21) / s, 0.25 * s, (m10 - m01) / s};
  }
  return q;
}

// Bones by name with their bind-pose world positions; rotations are all the identity, so a
// bone's translation is its world position minus its parent's.
class Skeleton {
 public:
  explicit Skeleton(ModelBuilder& builder) : builder_(builder) {}

  // A joint (in the skin) at world position `at`.
  int bone(const std::string& name, int parent, DVec3 at) {
    const int node = node_at(name, parent, at);
    joint_of_[node] = static_cast<int>(joints_.size());
    joints_.push_back(node);
    return node;
  }
  // A node that is not a joint (attach points, fingertips), optionally turned (bones never are).
  int node_at(const std::string& name, int parent, DVec3 at, Quat rotation = {0, 0, 0, 1}) {
    const DVec3 base = parent >= 0 ? world_.at(parent) : DVec3{0, 0, 0};
    const int node = builder_.add_node(name, -1, at - base, rotation);
    if (parent >= 0) {
      builder_.add_child(parent, node);
    } else {
      builder_.add_root(node);
    }
    world_[node] = at;
    return node;
  }
  DVec3 at(int node) const { return world_.at(node); }
  int joint(int node) const { return node < 0 ? -1 : joint_of_.at(node); }
  const std::vector<int>& joints() const { return joints_; }

 private:
  ModelBuilder& builder_;
  std::map<int, DVec3> world_;
  std::map<int, int> joint_of_;
  std::vector<int> joints_;
};

// A hand hanging from the wrist `wrist` (world), fingers down the arm, palm toward the body,
// thumb forward. `frame` maps the hand asset's frame (fingers -Z, palm -Y, middle MCP at the
// origin; README.md "Hands") onto the world about the wrist; it must be a rotation, which fixes
// the rig whose thumb side fits (`rig`). Bones "hand" + suffix and the fingers; grip + tips.
void add_hanging_hand(Skeleton& skeleton, MeshData& skin, const HandRig& rig,
                      const std::string& suffix, int forearm, DVec3 wrist, const Mat4& rotation) {
  const HandShape& shape = rig.data.shape;
  const double palm = shape.palm_length_mm / 1000.0;
  const DVec3 wrist_local{0.0, -0.004, palm};
  auto to_world = [&](DVec3 p) { return wrist + transform_point(rotation, p - wrist_local); };
  const Mat4 placement = multiply(compose(wrist, {0, 0, 0, 1}),
                                  multiply(rotation, compose(-1.0 * wrist_local, {0, 0, 0, 1})));
  const int hand = skeleton.bone("hand" + suffix, forearm, wrist);
  const int hand_joint = skeleton.joint(hand);

  // A relaxed hang: each joint curled a little toward the palm (positions only).
  constexpr double kCurlDeg[3] = {12.0, 18.0, 10.0};
  constexpr double kThumbCurlDeg[3] = {8.0, 10.0, 10.0};
  constexpr double kThumbOutDeg = 28.0;
  for (std::size_t fi = 0; fi < 5; ++fi) {
    const FingerRig& finger = rig.fingers[fi];
    const bool thumb = fi == 0;
    const double side = finger.root_mm[0] < 0.0 ? -1.0 : 1.0;
    DVec3 p = keyboard_to_gltf(finger.root_mm);
    double phi = 0.0;
    int parent = hand;
    const double base = thumb     ? shape.thumb_radius_mm
                        : fi == 4 ? shape.little_finger_radius_mm
                                  : shape.finger_radius_mm;
    const double total = finger.phalanges_mm[0] + finger.phalanges_mm[1] + finger.phalanges_mm[2];
    double along = 0.0;
    for (std::size_t s = 0; s < 3; ++s) {
      const int bone =
          skeleton.bone(std::string(kFingerNames[fi]) + "_" + std::to_string(s + 1) + suffix,
                        parent, to_world(p));
      phi += (thumb ? kThumbCurlDeg[s] : kCurlDeg[s]) * kPi / 180.0;
      const double out = thumb ? kThumbOutDeg * kPi / 180.0 : 0.0;
      const DVec3 dir{side * std::sin(out) * std::cos(phi), -std::sin(phi),
                      -std::cos(out) * std::cos(phi)};
      const double len = finger.phalanges_mm[s] / 1000.0;
      auto radius = [&](double at_mm) {
        return base / 1000.0 * (1.0 - (1.0 - shape.tip_radius_ratio) * at_mm / total);
      };
      const double r0 = radius(along);
      const double r1 = radius(along + finger.phalanges_mm[s]);
      const double end = s == 2 ? len - r1 : len;
      const std::size_t first = skin.vertex_count();
      add_capsule(skin, f3(p), f3(p + end * dir), f(r0), f(r1), 12);
      transform_vertices(skin, first, placement);
      weight_vertices(skin, first, static_cast<std::uint16_t>(skeleton.joint(bone)));
      p = p + len * dir;
      along += finger.phalanges_mm[s];
      parent = bone;
    }
    skeleton.node_at(std::string(kFingerNames[fi]) + "_tip" + suffix, parent, to_world(p));
  }

  // Palm: knuckle bar, the palm's body back to the wrist, the thumb's ball (as in add_hand).
  const std::size_t first = skin.vertex_count();
  const auto& index = rig.fingers[1].root_mm;
  const auto& little = rig.fingers[4].root_mm;
  const auto& thumb = rig.fingers[0].root_mm;
  add_capsule(skin, f3(keyboard_to_gltf(index)), f3(keyboard_to_gltf(little)),
              f((shape.finger_radius_mm + 1.5) / 1000),
              f((shape.little_finger_radius_mm + 1.5) / 1000), 12);
  const double x_lo = std::min(index[0], little[0]) - shape.palm_margin_mm;
  const double x_hi = std::max(index[0], little[0]) + shape.palm_margin_mm;
  const DVec3 palm_centre{(x_lo + x_hi) / 2000, -0.002, palm * 0.45};
  add_ellipsoid(skin, f3(palm_centre),
                {f((x_hi - x_lo) / 2000), f(shape.palm_thickness_mm / 2000), f(palm * 0.6)}, 20);
  const double heel_x = index[0] + (thumb[0] - index[0]) * 0.4;
  add_capsule(skin, f3(keyboard_to_gltf(thumb)), {f(heel_x / 1000), -0.004f, f(palm * 0.7)},
              f(shape.thumb_radius_mm * 1.1 / 1000), f(shape.thumb_radius_mm * 1.6 / 1000), 12);
  // The wrist, blending into the forearm.
  add_capsule(skin, f3(wrist_local + DVec3{0, 0, 0.02}), f3(wrist_local - DVec3{0, 0, 0.015}),
              0.026f, 0.025f, 16);
  transform_vertices(skin, first, placement);
  const int forearm_joint = skeleton.joint(forearm);
  const DVec3 up = to_world(wrist_local + DVec3{0, 0, 0.05}) - wrist;  // toward the elbow
  weight_with(skin, first, [&](DVec3 v) {
    const double toward_elbow = dot(v - wrist, up) / length(up) / length(up);  // 1 at 50 mm
    const double w = 0.5 * smooth(0.5 + toward_elbow);
    return Influence{{hand_joint, forearm_joint, -1, -1}, {1.0 - w, w, 0.0, 0.0}};
  });
  // The palm's centre, on its inner surface, turned into the hand asset's frame: an instrument's
  // grip node is in that frame, so the renderer turns the hand until the two frames agree.
  skeleton.node_at("grip" + suffix, hand,
                   to_world(palm_centre - DVec3{0, shape.palm_thickness_mm / 2000, 0}),
                   rotation_quat(rotation));
}

// A column-major rotation matrix from the images of the X, Y and Z axes.
Mat4 axes(DVec3 x, DVec3 y, DVec3 z) {
  return {x[0], x[1], x[2], 0, y[0], y[1], y[2], 0, z[0], z[1], z[2], 0, 0, 0, 0, 1};
}

// Falloff around the mouth: 1 at the centre, 0 on and outside the ellipsoid with radii `r`.
double falloff(DVec3 q, DVec3 r) {
  const double e =
      (q[0] / r[0]) * (q[0] / r[0]) + (q[1] / r[1]) * (q[1] / r[1]) + (q[2] / r[2]) * (q[2] / r[2]);
  return e >= 1.0 ? 0.0 : (1.0 - e) * (1.0 - e);
}

}  // namespace

tinygltf::Model build_performer(const PerformerDimensions& dims, const HandRig& right_hand,
                                const HandRig& left_hand) {
  ModelBuilder builder;
  const int suit_material = builder.add_material({"suit", {0.028, 0.030, 0.038, 1.0}, 0.0, 0.62});
  const int shirt_material = builder.add_material({"shirt", {0.80, 0.80, 0.78, 1.0}, 0.0, 0.55});
  const int skin_material = builder.add_material({"skin", {0.72, 0.45, 0.33, 1.0}, 0.0, 0.55});
  const int shoe_material =
      builder.add_material({"shoe_leather", {0.018, 0.016, 0.016, 1.0}, 0.0, 0.3});
  const int hair_material = builder.add_material({"hair", {0.045, 0.030, 0.022, 1.0}, 0.0, 0.7});
  const int eye_material = builder.add_material({"eye_white", {0.82, 0.80, 0.76, 1.0}, 0.0, 0.2});
  const int iris_material = builder.add_material({"iris", {0.035, 0.020, 0.012, 1.0}, 0.0, 0.15});
  const int mouth_material =
      builder.add_material({"mouth_inside", {0.16, 0.035, 0.035, 1.0}, 0.0, 0.6});

  auto mm = [](double v) { return v / 1000.0; };
  // Joint positions (bind pose, metres).
  const double hip_y = mm(dims.ankle_height_mm + dims.shin_length_mm + dims.thigh_length_mm);
  const double spine_y = hip_y + mm(dims.spine_length_mm);
  const double chest_y = spine_y + mm(dims.chest_length_mm);
  const double neck_y = chest_y + mm(dims.neck_base_mm);
  const double head_y = neck_y + mm(dims.neck_length_mm);
  const double hx = mm(dims.hip_width_mm) / 2;
  const double sx = mm(dims.shoulder_width_mm) / 2;
  const double spread = dims.arm_spread_deg * kPi / 180.0;

  Skeleton sk(builder);
  const int root = sk.node_at("performer", -1, {0, 0, 0});
  const int hips = sk.bone("hips", root, {0, hip_y, 0});
  const int spine = sk.bone("spine", hips, {0, spine_y, -0.01});
  const int chest = sk.bone("chest", spine, {0, chest_y, -0.005});
  const int neck = sk.bone("neck", chest, {0, neck_y, 0});
  const int head = sk.bone("head", neck, {0, head_y, 0.01});

  MeshData suit, shirt, skin, face, shoes, hair, eyes, irises, mouth_inside;

  // Torso: a surface of revolution (width profile) flattened front to back, the weights running
  // hips -> spine -> chest with height.
  {
    const std::size_t first = suit.vertex_count();
    Tube torso;
    const double profile[][2] = {
        {hip_y - 0.07, 0.150},   {hip_y, 0.172},         {hip_y + 0.07, 0.168},
        {spine_y + 0.04, 0.152}, {chest_y, 0.168},       {neck_y - 0.12, 0.180},
        {neck_y - 0.05, 0.172},  {neck_y - 0.015, 0.13}, {neck_y, 0.075}};
    for (const auto& [y, r] : profile) {
      torso.centres.push_back({0.0f, f(y), 0.0f});
      torso.radii.push_back(f(r));
    }
    torso.segments = 28;
    torso.start = Tube::End::rounded;
    torso.end = Tube::End::rounded;
    add_tube(suit, torso);
    scale_about(suit, first, {0, 0, 0}, {1.0, 1.0, 0.62});
    const int jh = sk.joint(hips), js = sk.joint(spine), jc = sk.joint(chest);
    weight_with(suit, first, [&](DVec3 p) {
      const double y = p[1];
      if (y <= hip_y + 0.02) return rigid(jh);
      if (y <= spine_y + 0.03) {
        const double w = smooth((y - hip_y - 0.02) / (spine_y - hip_y + 0.01));
        return Influence{{jh, js, -1, -1}, {1 - w, w, 0, 0}};
      }
      if (y <= chest_y + 0.04) {
        const double w = smooth((y - spine_y - 0.03) / (chest_y - spine_y + 0.01));
        return Influence{{js, jc, -1, -1}, {1 - w, w, 0, 0}};
      }
      return rigid(jc);
    });
  }

  // Arms: shoulder (clavicle) > upper arm > forearm > hand, hanging down and out (the A-pose).
  struct Side {
    const char* suffix;
    double sign;  // -1: at -X, which is the performer's right (they face +Z)
    const HandRig* rig;
    Mat4 hand_frame;
  };
  // The hand asset's frame (fingers -Z, palm -Y) turned so the fingers point down the arm, the
  // palm toward the body and the thumb forward (+Z); each side uses the rig whose thumb lies
  // that way without a mirror.
  const Side sides[2] = {{"_r", -1.0, &right_hand,
                          multiply(compose({0, 0, 0}, rotation_about({0, 0, 1}, -spread)),
                                   axes({0, 0, -1}, {-1, 0, 0}, {0, 1, 0}))},
                         {"_l", 1.0, &left_hand,
                          multiply(compose({0, 0, 0}, rotation_about({0, 0, 1}, spread)),
                                   axes({0, 0, 1}, {1, 0, 0}, {0, 1, 0}))}};
  for (const Side& s : sides) {
    const std::string x = s.suffix;
    const DVec3 down{s.sign * std::sin(spread), -std::cos(spread), 0.0};
    const DVec3 clavicle{s.sign * 0.03, neck_y - 0.03, 0.0};
    const DVec3 shoulder_at{s.sign * sx, neck_y - 0.035, -0.01};
    const DVec3 elbow = shoulder_at + mm(dims.upper_arm_length_mm) * down;
    const DVec3 wrist = elbow + mm(dims.forearm_length_mm) * down;
    const int shoulder = sk.bone("shoulder" + x, chest, clavicle);
    const int upper = sk.bone("upper_arm" + x, shoulder, shoulder_at);
    const int fore = sk.bone("forearm" + x, upper, elbow);
    const int jc = sk.joint(chest), jsh = sk.joint(shoulder), ju = sk.joint(upper),
              jf = sk.joint(fore);
    // Shoulder line: from the neck out to the shoulder, then the deltoid's roundness.
    std::size_t first = suit.vertex_count();
    const DVec3 neck_side{s.sign * 0.045, neck_y - 0.012, -0.01};
    add_limb(suit, neck_side, shoulder_at + DVec3{0, 0.005, 0}, 0.045, 0.056, 6);
    weight_with(suit, first, [&](DVec3 p) {
      return limb_influence(p, neck_side, shoulder_at, jc, jsh, ju, 0.05);
    });
    first = suit.vertex_count();
    add_sphere(suit, f3(shoulder_at + DVec3{0, -0.005, 0}), 0.058f, 16);
    weight_with(suit, first, [&](DVec3) { return Influence{{ju, jsh, -1, -1}, {0.6, 0.4, 0, 0}}; });
    // Sleeves (the jacket), the shirt cuff at the wrist.
    first = suit.vertex_count();
    add_limb(suit, shoulder_at, elbow, 0.050, 0.041, 10);
    weight_with(suit, first,
                [&](DVec3 p) { return limb_influence(p, shoulder_at, elbow, jsh, ju, jf, 0.06); });
    const DVec3 sleeve_end = wrist - 0.03 * down;
    first = suit.vertex_count();
    add_limb(suit, elbow, sleeve_end, 0.040, 0.035, 10);
    weight_with(suit, first,
                [&](DVec3 p) { return limb_influence(p, elbow, sleeve_end, ju, jf, -1, 0.06); });
    first = shirt.vertex_count();
    add_limb(shirt, wrist - 0.045 * down, wrist - 0.01 * down, 0.031, 0.030, 3);
    weight_vertices(shirt, first, static_cast<std::uint16_t>(jf));
    add_hanging_hand(sk, skin, *s.rig, x, fore, wrist, s.hand_frame);
  }

  // Legs: thigh > shin > foot straight down; trousers to the shoe, the shoes on the floor.
  const double ankle_y = mm(dims.ankle_height_mm);
  const double foot = mm(dims.foot_length_mm);
  std::array<int, 2> foot_bones{-1, -1};
  for (const Side& s : sides) {
    const std::string x = s.suffix;
    const DVec3 hip{s.sign * hx, hip_y, 0.0};
    const DVec3 knee{s.sign * hx, hip_y - mm(dims.thigh_length_mm), 0.0};
    const DVec3 ankle{s.sign * hx, ankle_y, 0.0};
    const int thigh = sk.bone("thigh" + x, hips, hip);
    const int shin = sk.bone("shin" + x, thigh, knee);
    const int foot_bone = sk.bone("foot" + x, shin, ankle);
    foot_bones[&s == &sides[0] ? 0 : 1] = foot_bone;
    const int jh = sk.joint(hips), jt = sk.joint(thigh), js = sk.joint(shin),
              jft = sk.joint(foot_bone);
    std::size_t first = suit.vertex_count();
    const DVec3 thigh_top = hip + DVec3{-s.sign * 0.005, 0.03, 0.0};
    add_limb(suit, thigh_top, knee, 0.088, 0.058, 8, 16);
    weight_with(suit, first,
                [&](DVec3 p) { return limb_influence(p, thigh_top, knee, jh, jt, js, 0.08); });
    first = suit.vertex_count();
    const DVec3 cuff{s.sign * hx, ankle_y + 0.01, 0.005};
    add_limb(suit, knee, cuff, 0.057, 0.050, 8, 16);
    weight_with(suit, first,
                [&](DVec3 p) { return limb_influence(p, knee, cuff, jt, js, jft, 0.06); });
    // The shoe: a rounded last, heel 50 mm behind the ankle, the sole on the floor.
    first = shoes.vertex_count();
    const double toe_z = foot - 0.05;
    add_ellipsoid(shoes, f3({s.sign * hx, 0.042, (toe_z - 0.05) / 2}),
                  {0.050f, 0.042f, f(foot / 2)}, 28);
    add_capsule(shoes, f3(ankle + DVec3{0, -0.01, -0.01}), f3(ankle + DVec3{0, -0.03, 0.05}),
                0.045f, 0.044f, 20);
    weight_vertices(shoes, first, static_cast<std::uint16_t>(jft));
  }

  // Neck, collar and bow tie.
  {
    const std::size_t first = skin.vertex_count();
    const DVec3 a{0, neck_y - 0.03, -0.005};
    const DVec3 b{0, head_y + 0.04, 0.0};
    add_limb(skin, a, b, 0.052, 0.049, 6, 16);
    weight_with(skin, first, [&](DVec3 p) {
      return limb_influence(p, a, b, sk.joint(chest), sk.joint(neck), sk.joint(head), 0.04);
    });
    std::size_t at = shirt.vertex_count();
    Tube collar;
    collar.centres = {{0.0f, f(neck_y - 0.025), 0.0f}, {0.0f, f(neck_y + 0.035), 0.003f}};
    collar.radii = {0.064f, 0.058f};
    collar.segments = 28;
    add_tube(shirt, collar);
    weight_with(shirt, at, [&](DVec3 p) {
      const double w = smooth((p[1] - neck_y + 0.025) / 0.06);
      return Influence{{sk.joint(chest), sk.joint(neck), -1, -1}, {1 - w, w, 0, 0}};
    });
    at = shirt.vertex_count();
    add_ellipsoid(shirt, f3({0, neck_y - 0.055, 0.086}), {0.036f, 0.06f, 0.024f}, 20);
    weight_vertices(shirt, at, static_cast<std::uint16_t>(sk.joint(chest)));
    at = suit.vertex_count();
    add_sphere(suit, f3({0, neck_y + 0.004, 0.066}), 0.009f, 12);
    for (const double side : {-1.0, 1.0}) {
      add_ellipsoid(suit, f3({side * 0.02, neck_y + 0.004, 0.062}), {0.022f, 0.013f, 0.007f}, 16);
    }
    weight_vertices(suit, at, static_cast<std::uint16_t>(sk.joint(neck)));
  }

  // Head: everything in head-local metres, scaled by the head's height (230 mm = 1), relative to
  // the head joint (chin height).
  const double k = dims.head_height_mm / 230.0;
  const DVec3 h0 = sk.at(head);
  auto hp = [&](double x, double y, double z) { return h0 + k * DVec3{x, y, z}; };
  const DVec3 cranium_c{0, 0.115, 0.008};
  const DVec3 cranium_r{0.076, 0.115, 0.099};
  const DVec3 jaw_c{0, 0.062, 0.023};
  const DVec3 jaw_r{0.062, 0.069, 0.078};
  // z of an ellipsoid's front surface at (x, y), head-local.
  auto front_z = [](DVec3 c, DVec3 r, double x, double y) {
    const double e =
        1.0 - ((x - c[0]) / r[0]) * ((x - c[0]) / r[0]) - ((y - c[1]) / r[1]) * ((y - c[1]) / r[1]);
    return c[2] + r[2] * std::sqrt(std::max(e, 0.0));
  };
  const double mouth_y = 0.055;
  auto face_z = [&](double x, double y) {
    return std::max(front_z(jaw_c, jaw_r, x, y), front_z(cranium_c, cranium_r, x, y));
  };
  auto ellipsoid = [&](MeshData& mesh, DVec3 c, DVec3 r, int segments) {
    add_ellipsoid(mesh, f3(hp(c[0], c[1], c[2])), f3(k * r), segments);
  };
  ellipsoid(face, cranium_c, cranium_r, 32);
  ellipsoid(face, jaw_c, jaw_r, 40);
  for (const double side : {-1.0, 1.0}) {
    ellipsoid(face, {side * 0.036, 0.082, 0.05}, {0.028, 0.026, 0.03}, 24);    // cheeks
    ellipsoid(face, {side * 0.076, 0.112, -0.004}, {0.011, 0.03, 0.018}, 16);  // ears
  }
  // Nose: bridge, tip, wings.
  add_capsule(face, f3(hp(0, 0.148, face_z(0, 0.148) - 0.004)), f3(hp(0, 0.102, 0.106)),
              f(k * 0.0075), f(k * 0.010), 16);
  ellipsoid(face, {0, 0.097, 0.107}, {0.011, 0.010, 0.011}, 20);
  for (const double side : {-1.0, 1.0}) {
    ellipsoid(face, {side * 0.012, 0.093, 0.100}, {0.009, 0.007, 0.008}, 16);
  }
  // Lips: two tapered tubes following the face's curve.
  double lip_front = 0.0;
  for (int lip = 0; lip < 2; ++lip) {
    const double y = lip == 0 ? mouth_y + 0.0042 : mouth_y - 0.0048;
    const double half = lip == 0 ? 0.024 : 0.022;
    const double radius = lip == 0 ? 0.0052 : 0.0064;
    Tube tube;
    for (int i = 0; i <= 10; ++i) {
      const double x = -half + 2 * half * i / 10.0;
      const double u = x / half;
      tube.centres.push_back(f3(hp(x, y, face_z(x, y) + 0.0005)));
      tube.radii.push_back(f(k * radius * (1.0 - 0.6 * u * u)));
    }
    tube.segments = 16;
    tube.start = Tube::End::rounded;
    tube.end = Tube::End::rounded;
    add_tube(face, tube);
    lip_front = std::max(lip_front, face_z(0, y) + 0.0005 + radius);
  }
  weight_vertices(face, 0, static_cast<std::uint16_t>(sk.joint(head)));
  const DVec3 mouth_at = hp(0, mouth_y - 0.0003, lip_front);
  sk.node_at("mouth", head, mouth_at);
  // Where a shoe's sole presses an organ pedal: under the ball of the foot (made after every
  // other node, so theirs keep their indices).
  for (std::size_t i = 0; i < 2; ++i) {
    sk.node_at("toe" + std::string(sides[i].suffix), foot_bones[i],
               {sides[i].sign * hx, 0.01, (foot - 0.05) / 2 + 0.085});
  }

  // The mouth's inside, hidden behind closed lips, seen when they open.
  ellipsoid(mouth_inside, {0, mouth_y - 0.001, face_z(0, mouth_y) - 0.0005}, {0.019, 0.008, 0.0035},
            20);
  weight_vertices(mouth_inside, 0, static_cast<std::uint16_t>(sk.joint(head)));

  // Eyes (white, dark iris), brows, hair cap.
  for (const double side : {-1.0, 1.0}) {
    const double ex = side * 0.032;
    const double ey = 0.142;
    const double ez = face_z(ex, ey) - 0.0072;
    const double er = 0.0125;
    add_sphere(eyes, f3(hp(ex, ey, ez)), f(k * er), 16);
    ellipsoid(irises, {ex, ey, ez + er - 0.0014}, {0.0058, 0.0058, 0.0024}, 20);
    const double by = 0.163;
    add_capsule(hair, f3(hp(side * 0.014, by, face_z(side * 0.014, by) + 0.001)),
                f3(hp(side * 0.049, by + 0.004, face_z(side * 0.049, by + 0.004) + 0.001)),
                f(k * 0.0042), f(k * 0.0028), 12);
  }
  weight_vertices(eyes, 0, static_cast<std::uint16_t>(sk.joint(head)));
  weight_vertices(irises, 0, static_cast<std::uint16_t>(sk.joint(head)));
  {
    MeshData cap;
    add_ellipsoid(cap, f3(hp(0, 0.119, 0.004)), f3(k * (cranium_r + DVec3{0.006, 0.006, 0.006})),
                  48);
    // Keep the hair above a hairline: high at the forehead, down to the nape at the back.
    append_where(hair, cap, [&](DVec3 p) {
      const DVec3 q = (1.0 / k) * (p - h0);
      const double back = std::clamp((0.07 - q[2]) / 0.09, 0.0, 1.0);  // 0 front, 1 back
      const double line = 0.192 - 0.085 * back;
      return q[1] > line && !(std::abs(q[0]) > 0.06 && q[1] < 0.15 && q[2] > -0.03);
    });
  }
  weight_vertices(hair, 0, static_cast<std::uint16_t>(sk.joint(head)));

  // Morph targets on the face: deltas only near the mouth (falloff ellipsoids within 50 mm).
  {
    MorphTarget tension{"tension", {}, {}};
    MorphTarget open{"open", {}, {}};
    tension.normals.assign(face.normals.size(), 0.0f);
    open.normals.assign(face.normals.size(), 0.0f);
    for (std::size_t v = 0; v < face.vertex_count(); ++v) {
      const DVec3 p{face.positions[3 * v], face.positions[3 * v + 1], face.positions[3 * v + 2]};
      const DVec3 q = (1.0 / k) * (p - mouth_at);
      // Tension: the corners drawn in, the lips pressed together and firmed back against the
      // rim, the chin's skin tightened up.
      const double ft = falloff(q, {0.045, 0.032, 0.03});
      const double toward_line = q[1] > 0 ? -1.0 : 1.0;
      const DVec3 dt{-0.2 * q[0] * ft, toward_line * 0.0016 * ft * smooth(std::abs(q[1]) / 0.004),
                     -0.0018 * ft};
      // Open: the lower lip and the skin under it drop, the upper lip lifts a little, the corners
      // less than the middle (an oval).
      const double fo = falloff(q, {0.034, 0.045, 0.035});
      const double below = 1.0 - smooth((q[1] + 0.002) / 0.004);  // 1 under the lip line
      const DVec3 dopen{0.0, (-0.011 * below + 0.0028 * (1.0 - below)) * fo, -0.003 * below * fo};
      for (std::size_t c = 0; c < 3; ++c) {
        tension.positions.push_back(f(k * dt[c]));
        open.positions.push_back(f(k * dopen[c]));
      }
    }
    face.targets = {tension, open};
  }

  // One skin over every bone; each mesh a scene root without transform.
  const int skin_index = builder.add_skin("performer", sk.joints(), hips);
  auto add = [&](const std::string& name, const MeshData& data, int material) {
    if (data.vertex_count() == 0) return;
    const int node = builder.add_node(name + "_mesh", builder.add_mesh(name, data, material));
    builder.set_skin(node, skin_index);
    builder.add_root(node);
  };
  add("performer_face", face, skin_material);
  add("performer_skin", skin, skin_material);
  add("performer_suit", suit, suit_material);
  add("performer_shirt", shirt, shirt_material);
  add("performer_shoes", shoes, shoe_material);
  add("performer_hair", hair, hair_material);
  add("performer_eyes", eyes, eye_material);
  add("performer_irises", irises, iris_material);
  add("performer_mouth", mouth_inside, mouth_material);
  return builder.finish();
}

}  // namespace tutti::content_generator
