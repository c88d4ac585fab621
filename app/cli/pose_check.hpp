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
#include <tutti/stage/pose_checker.hpp>
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

// The measures and the report: stage/pose_checker.hpp.
using PoseMeasure = stage::PoseMeasure;
using PoseReport = stage::PoseReport;

// Poses `stage` at every frame of the options' range and measures every performer the stage has
// by their family's measures (FamilyPlugin::check_pose; the default families'):
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
Result<PoseReport> check_pose(const stage::Stage& stage, const PoseCheckOptions& options);

// The report as a table, one measure a line: samples, median, p95, max, limit, ok.
std::string format_pose_report(const PoseReport& report);

}  // namespace tutti::cli
