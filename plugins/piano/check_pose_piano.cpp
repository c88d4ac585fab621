// SPDX-License-Identifier: MIT
// The keyboard family's `check-pose` measures (stage/pose_checker.hpp): each pressing fingertip's
// pad on its key's top at key bottom, one hand never inside the other, keys left hanging half
// down with no note sounding, an organist's toes on their pedals, and the measures every family
// shares (joint speeds, fingertips clear of the head).
#include <algorithm>
#include <array>
#include <cmath>
#include <map>
#include <string>
#include <tutti/components/finger.hpp>
#include <tutti/piano/hand_capsules.hpp>
#include <tutti/piano/piano_components.hpp>
#include <tutti/piano/piano_plugin.hpp>
#include <tutti/piano/pose_feet.hpp>
#include <tutti/piano_model/pedal_geometry.hpp>
#include <tutti/stage/body_retarget.hpp>
#include <tutti/stage/pose_checker.hpp>
#include <vector>

namespace tutti::piano {
namespace {

using stage::origin;
using stage::PoseMeasure;
using stage::pose::kFingerNames;
using stage::pose::kPadRadiusMm;
using FingerNodes = stage::PoseChecker::FingerNodes;

// Each keyboard player's keys over the checked range (seconds summed over keys).
struct KeyTally {
  double all_seconds = 0.0;   // every animated key
  double down_seconds = 0.0;  // keys off their rest
  double mid_silent = 0.0;    // half down with no note of the key sounding
  double mid_resting = 0.0;   // ... and not being struck or released
  int hanging_key = -1;       // the first key seen left hanging, and when
  double hanging_at_s = 0.0;
};

// What the measures keep across frames (PoseChecker::family_state).
struct State {
  std::map<std::string, KeyTally> key_tallies;            // by player
  std::array<std::vector<HandCapsule>, 2> hand_capsules;  // the player just posed: right, left
};
constexpr const char* kStateKey = "keyboards";

// An organist's toes: each one holding its pedal all the way down is on the pedal's top, inside
// its outline (in the pedal's frame: x across, y up from the top, z along from the hinge).
void toes_on_pedals(stage::PoseChecker& c, const std::string& who, const PianoRig& rig,
                    double t_s) {
  using piano_model::PedalGeometry;
  for (int foot : {kRightFoot, kLeftFoot}) {
    const components::Foot* state = foot_of(c.world(), rig, foot);
    if (state == nullptr || state->press_depth < 0.999 || state->key < 0 || state->key > 127) {
      continue;
    }
    const int pedal = rig.pedal_nodes[static_cast<std::size_t>(state->key)];
    const int toe = foot == kRightFoot ? rig.body_nodes.toe_right : rig.body_nodes.toe_left;
    if (pedal < 0 || toe < 0) continue;
    const glm::vec3 local = glm::inverse(c.instrument_world()[static_cast<std::size_t>(pedal)]) *
                            glm::vec4(origin(c.body_world()[static_cast<std::size_t>(toe)]), 1.0f);
    const double length = piano_model::pedal_is_sharp(state->key) ? PedalGeometry::kSharpLength_m
                                                                  : PedalGeometry::kNaturalLength_m;
    const double off_side =
        std::max(0.0, std::abs(static_cast<double>(local.x)) - PedalGeometry::kPedalWidth_m / 2.0);
    const double off_end =
        std::max({0.0, -static_cast<double>(local.z), static_cast<double>(local.z) - length});
    const double off_top = std::abs(static_cast<double>(local.y));
    c.measure(who + ": pressing toe off its pedal's top (0 = on it)", "mm", 3.0)
        .add(std::sqrt(off_side * off_side + off_end * off_end + off_top * off_top) * 1000.0, t_s,
             std::string(foot == kRightFoot ? "right" : "left") + " toe on pedal " +
                 std::to_string(state->key));
  }
}

// The pianist's hand `side` as capsules (world space): each finger's bones, knuckle to tip, and
// the palm across the knuckles. From a user's hands (`own`) or tutti's hand model.
void hand_capsules_of(stage::PoseChecker& c, State& state, const PianoRig& rig, std::size_t side,
                      const stage::PlacedModel* own, const stage::BodyNodes* own_nodes,
                      std::size_t body_side, const stage::PlacedModel* hand) {
  std::vector<HandCapsule>& out = state.hand_capsules[side];
  out.clear();
  const std::vector<glm::mat4>* world = nullptr;
  FingerChains chain{};
  if (own != nullptr) {
    world =
        rig.hands_retarget && own == &rig.hands_retarget->proxy ? &c.hand_world() : &c.body_world();
    for (std::size_t f = 0; f < 5; ++f) {
      for (std::size_t j = 0; j < 3; ++j) chain[f][j] = own_nodes->fingers[body_side][f][j];
      chain[f][3] = own_nodes->fingertips[body_side][f];
    }
  } else if (hand != nullptr) {
    world = &c.hand_world();
    for (std::size_t f = 0; f < 5; ++f) {
      for (std::size_t j = 0; j < 3; ++j) chain[f][j] = rig.finger_bones[side][f][j];
      chain[f][3] = rig.finger_tips[side][f];
    }
  } else {
    return;
  }
  piano::collect_hand_capsules(chain, *world, out);
}

// How deep one hand's capsules reach into the other's: hands cross over each other, never
// through.
void hands_apart(stage::PoseChecker& c, const State& state, const std::string& who) {
  if (state.hand_capsules[0].empty() || state.hand_capsules[1].empty()) return;
  double depth = 0.0;
  const HandCapsule* deepest_right = nullptr;
  const HandCapsule* deepest_left = nullptr;
  for (const HandCapsule& right : state.hand_capsules[0]) {
    for (const HandCapsule& left : state.hand_capsules[1]) {
      const double into = overlap_m(right, left);
      if (into > depth) depth = into, deepest_right = &right, deepest_left = &left;
    }
  }
  c.measure(who + ": one hand inside the other (depth; 0 = apart)", "mm", 0.0)
      .add(depth * 1000.0, c.t_s(),
           deepest_right == nullptr
               ? std::string()
               : std::string("right ") + deepest_right->name + " in left " + deepest_left->name);
}

// One keyboard player in the frame just posed: the pressing pads on their keys, the hands apart,
// the keys' travel against the notes sounding, the toes on their pedals, the shared measures.
void check_keyboard_player(stage::PoseChecker& c, ecs::Entity performer, const PianoRig& rig) {
  const double t_s = c.t_s();
  const double dt_s = c.dt_s();
  State& state = c.family_state<State>(kStateKey);
  const ecs::World& world = c.world();
  const auto* piano = world.try_get<stage::PlacedModel>(rig.piano);
  if (piano == nullptr) return;
  const std::string who = c.performer_name(performer);
  stage::pose::world_of(*piano, c.instrument_world());
  std::vector<glm::vec3> tips;
  // A user's hands play: a hand model's stand-in, else a user's character's own (its
  // stand-in's fingertips and last joints).
  const auto* body =
      stage::posed_body(world.try_get<stage::PlacedModel>(rig.body), rig.body_retarget);
  if (body != nullptr) {
    stage::pose::world_of(*body, c.body_world());
    c.joint_speeds(who, *body, rig.body_nodes.fingers);
  }
  const stage::PlacedModel* own = nullptr;
  const stage::BodyNodes* own_nodes = nullptr;
  if (rig.hands_retarget) {
    own = &rig.hands_retarget->proxy;
    own_nodes = &rig.hands_nodes;
    stage::pose::world_of(*own, c.hand_world());
  } else if (rig.body_retarget && body != nullptr) {
    own = body;
    own_nodes = &rig.body_nodes;
  }
  for (std::size_t side = 0; side < 2; ++side) {
    const auto* hand = world.try_get<stage::PlacedModel>(rig.hand_models[side]);
    if (hand != nullptr && own == nullptr) {
      stage::pose::world_of(*hand, c.hand_world());
      FingerNodes fingers;
      for (auto& hand_fingers : fingers) {
        for (auto& finger : hand_fingers) finger.fill(-1);
      }
      fingers[0] = rig.finger_bones[side];
      c.joint_speeds(who, *hand, fingers);
    }
    const std::size_t body_side = side == 0 ? 1 : 0;  // the rig's _r is its side 1
    // The fingertip and its last joint (-1 when the hand has none).
    const auto joints = [&](std::size_t f, glm::vec3& tip, glm::vec3& dip) {
      if (own != nullptr) {
        const int t = own_nodes->fingertips[body_side][f];
        const int d = own_nodes->fingers[body_side][f][2];
        if (t < 0 || d < 0) return false;
        const std::vector<glm::mat4>& w = own == body ? c.body_world() : c.hand_world();
        tip = origin(w[static_cast<std::size_t>(t)]);
        dip = origin(w[static_cast<std::size_t>(d)]);
        return true;
      }
      if (hand == nullptr) return false;
      const std::string suffix = side == 0 ? "_r" : "_l";
      const int t = hand->asset->find_node(std::string(kFingerNames[f]) + "_tip" + suffix);
      if (t < 0) return false;
      tip = origin(c.hand_world()[static_cast<std::size_t>(t)]);
      const int d = hand->asset->find_node(std::string(kFingerNames[f]) + "_3" + suffix);
      dip = d >= 0 ? origin(c.hand_world()[static_cast<std::size_t>(d)]) : tip + glm::vec3(0, 1, 0);
      return true;
    };
    hand_capsules_of(c, state, rig, side, own, own_nodes, body_side, hand);
    for (std::size_t f = 0; f < 5; ++f) {
      glm::vec3 tip, dip;
      if (!joints(f, tip, dip)) continue;
      tips.push_back(tip);
      const auto* finger = world.try_get<components::Finger>(rig.fingers[side][f]);
      if (finger == nullptr || finger->press_depth < 0.999 || finger->key < 0 ||
          finger->key > 127) {
        continue;
      }
      const int key_node = rig.key_nodes[static_cast<std::size_t>(finger->key)];
      if (key_node < 0) continue;
      // The key's top surface is its node's y = 0 plane (the pivot at the top's back edge). The
      // flesh ends in a rounded cap whose outermost point is the tip node: the pad's lowest
      // point is the cap's centre less its radius.
      const glm::vec3 last_bone = tip - dip;
      const float radius = static_cast<float>(kPadRadiusMm[f] / 1000.0);
      const glm::vec3 cap_centre = tip - radius * glm::normalize(last_bone);
      const glm::mat4 key_frame =
          glm::inverse(c.instrument_world()[static_cast<std::size_t>(key_node)]);
      const glm::vec3 centre_local = key_frame * glm::vec4(cap_centre, 1.0f);
      // Key frames carry no scale: a length in it is a length in the world.
      // The thumb strikes with the side of its tip: reported on its own.
      PoseMeasure& pad = c.measure(who + (f == 0 ? ": thumb's" : ": pressing fingertip's") +
                                       " pad above its key's top at key bottom",
                                   "mm", 3.0);
      pad.two_sided = true;
      // The pad's lowest point over the key's top: off its outline (a black key struck in front
      // of its front edge, a key missed to the side) it presses nothing.
      // The key's outline, from its mesh when the rig was bound (PianoRig::key_half_width_mm).
      const auto key = static_cast<std::size_t>(finger->key);
      const double half_width_m = rig.key_half_width_mm[key] / 1000.0;
      const double length_m = rig.key_length_mm[key] / 1000.0;
      const double off_side =
          std::max(0.0, std::abs(static_cast<double>(centre_local.x)) - half_width_m);
      const double off_end = std::max({0.0, -static_cast<double>(centre_local.z),
                                       static_cast<double>(centre_local.z) - length_m});
      c.measure(who + ": pressing pad off its key's top (0 = on it)", "mm", 1.0)
          .add(
              std::hypot(off_side, off_end) * 1000.0, c.t_s(),
              (side == 0 ? "right " : "left ") + std::string(kFingerNames[f]) + " on key " +
                  std::to_string(finger->key) +
                  (off_end > off_side ? (centre_local.z > 0.0f ? ", in front of it" : ", behind it")
                                      : ", beside it"));
      pad.add((static_cast<double>(centre_local.y) - kPadRadiusMm[f] / 1000.0) * 1000.0, c.t_s(),
              (side == 0 ? "right " : "left ") + std::string(kFingerNames[f]) + " on key " +
                  std::to_string(finger->key));
    }
  }
  hands_apart(c, state, who);
  // The keys: how far each is down, and whether a note of it sounds (or is being struck or
  // released: 0.1 s before the onset to 0.1 s after the offset).
  KeyTally& tally = state.key_tallies[who];
  for (int key = 0; key < 128; ++key) {
    const int node = rig.key_nodes[static_cast<std::size_t>(key)];
    const double dip = rig.key_dip_rad[static_cast<std::size_t>(key)];
    if (node < 0 || dip <= 0.0) continue;
    tally.all_seconds += dt_s;
    const glm::quat& r = piano->pose.local[static_cast<std::size_t>(node)].rotation;
    const double angle =
        2.0 * std::asin(std::min(1.0, static_cast<double>(glm::length(glm::vec3(r.x, r.y, r.z)))));
    const double down = angle / dip;
    if (down <= 1e-4) continue;
    bool sounding = false;
    bool striking = false;
    for (const auto& [e, note] : c.notes()) {
      if (note->pitch != key || note->performer != performer) continue;
      sounding = sounding || note->sounding;
      striking = striking || (t_s >= note->onset_s - 0.1 && t_s <= note->offset_s + 0.1);
    }
    tally.down_seconds += dt_s;
    if (down > 0.25 && down < 0.75 && !sounding) {
      tally.mid_silent += dt_s;
      if (!striking) {
        tally.mid_resting += dt_s;
        if (tally.hanging_key < 0) tally.hanging_key = key, tally.hanging_at_s = t_s;
      }
    }
  }
  if (body != nullptr) toes_on_pedals(c, who, rig, t_s);
  if (body != nullptr) c.head_clearance(who, rig.body_nodes.head, tips);
}

void finish_keyboard_players(stage::PoseChecker& c) {
  const State& state = c.family_state<State>(kStateKey);
  for (const auto& [who, tally] : state.key_tallies) {
    if (tally.down_seconds <= 0.0) continue;
    // Of every animated key's seconds (all the piano's keys over the range): the figure.
    c.measure(who + ": keys half down (25-75 %), no note sounding, of all keys' seconds", "%", 1.0)
        .add(100.0 * tally.mid_silent / tally.all_seconds, c.t_s());
    // Of the seconds keys are off their rest (stricter, informational): a key passes through
    // half travel before its hammer escapes and after its damper falls, on every stroke and
    // release.
    c.measure(who + ": key-seconds half down (25-75 %) with no note of the key sounding", "%")
        .add(100.0 * tally.mid_silent / tally.down_seconds, c.t_s());
    c.measure(who + ": ... of them outside the keys' strokes (a key left hanging)", "%", 1.0)
        .add(100.0 * tally.mid_resting / tally.down_seconds, tally.hanging_at_s,
             tally.hanging_key < 0 ? std::string()
                                   : "the first: key " + std::to_string(tally.hanging_key));
  }
}

}  // namespace

void PianoPlugin::check_pose(stage::PoseChecker& checker, ecs::Entity performer) const {
  if (const auto* rig = checker.world().try_get<PianoRig>(performer)) {
    check_keyboard_player(checker, performer, *rig);
  }
}

void PianoPlugin::finish_pose_check(stage::PoseChecker& checker) const {
  finish_keyboard_players(checker);
}

}  // namespace tutti::piano
