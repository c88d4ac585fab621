// SPDX-License-Identifier: MIT
#pragma once
// Contacts as measured facts: the staged scene posed frame by frame and the posed skeletons read
// back — where fingertips are against the buttons and keys they press, where the hands are against
// the instruments they hold, whether a hand passes through a head, whether a piano key hangs half
// down with nothing sounding. `tutti check-pose SCENE` prints these figures; the tests hold the
// bundled scenes to them.

#include <cstddef>
#include <filesystem>
#include <string>
#include <vector>

#include <tutti/core/result.hpp>
#include <tutti/stage/stage.hpp>

namespace tutti::cli {

struct PoseCheckOptions {
  double from_s = 0.0;  // music time of the first frame
  double to_s = 12.0;   // frames with time < to_s
  int fps = 30;
  // Where hand_rig.json (the fingers' joint limits) is: <content_dir>/generator/. Empty: the
  // default content folder.
  std::filesystem::path content_dir;
};

// One figure over the frames it applies to: a distance (mm) or a share (%).
struct PoseMeasure {
  std::string name;     // "Trumpet 1: pressing fingertip to its button top"
  std::string unit;     // "mm", "%"
  std::vector<double> samples;  // one per frame (and finger, hand, ...) it applied to
  double limit = -1.0;          // the most allowed for `worst` (p95 if by_p95), < 0: no limit
  bool by_p95 = false;
  bool two_sided = false;  // the limit bounds |sample| (a signed distance: above or into)
  // Where the worst sample (the largest, or the largest |x| when two-sided) was: its music time
  // and what it was of ("right index on key 64"), so a figure over its limit can be looked at.
  double worst_at_s = 0.0;
  std::string worst_of;

  // Adds a sample taken at music time `t_s`; `of` names what it measured (may be empty).
  void add(double value, double t_s, const std::string& of = {});

  double percentile(double p) const;  // of the samples; 0 when there are none
  double worst() const { return percentile(1.0); }
  bool within_limit() const;

  std::size_t worst_index_ = 0;  // of samples; kept by add()
};

struct PoseReport {
  std::vector<PoseMeasure> measures;
  std::size_t frames = 0;
  const PoseMeasure* find(const std::string& name) const;
};

// Poses `stage` at every frame of the options' range and measures, for every performer the
// stage has:
//  - brass, valves: each pressing fingertip (the finger the hold puts on that valve) to its
//    button's top while the valve is down (mm; limit p95 ≤ 10);
//  - brass: each palm the hold puts on a grip to it (the trumpet's left palm round the valve
//    casings, the trombone's right palm on the slide grip, ...; mm, ≤ 20), and the trombone's
//    right palm while the slide moves;
//  - piano: the pressing fingertip's pad to its key's top surface at key bottom (mm; negative:
//    into the key); key-seconds with a key between 25 % and 75 % down and no note of it sounding,
//    as a share of the keys' animated key-seconds — all of them, and outside the strokes of its
//    notes (from 0.1 s before an onset to 0.1 s after the offset);
//  - everyone: how deep hands, fingertips and elbows go into the head's or the torso's capsule
//    (mm; 0 = outside); how far the fingers (index .. little, tutti's rig) bend or spread past
//    their joint limits (degrees; content/generator/hand_rig.json).
Result<PoseReport> check_pose(stage::Stage& stage, const PoseCheckOptions& options);

// The report as a table, one measure a line: samples, median, p95, max, limit, ok.
std::string format_pose_report(const PoseReport& report);

}  // namespace tutti::cli
