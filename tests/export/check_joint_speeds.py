#!/usr/bin/env python3
# SPDX-License-Identifier: MIT
"""How fast each joint of a `tutti export` .glb turns, from its own animation and none of tutti's
code: every rotation channel of the whole-scene clip sampled at the export's frames (LINEAR:
slerp; STEP), the angle between consecutive frames' rotations times the fps.

  check_joint_speeds.py FILE.glb

Limits (deg/s, as `tutti check-pose` states them): finger joints (thumb_, index_, middle_,
ring_, little_) 2500; a trombonist's slide arm (upper_arm_r, forearm_r, hand_r below a root
named for a trombone player) 2000 (check-pose: while the slide moves); every other joint of a
body 1000 (check-pose lets arms past it within a stroke or a cue; none needs it here). Bodies and
hands only: the instruments (the models the file's contacts touch: keys, valves, rotors) are
left out. Prints the fastest joints; exits 1 over a limit, 2 on a file it
cannot read."""

import math
import sys

from check_contacts import Posed, fail, read_glb

FINGER_PREFIXES = ("thumb_", "index_", "middle_", "ring_", "little_")
SLIDE_ARM = ("upper_arm_r", "forearm_r", "hand_r")


def limit_for(root_name, node_name):
    if node_name.startswith(FINGER_PREFIXES):
        return 2500.0
    if "trombone" in root_name.lower() and node_name in SLIDE_ARM:
        return 2000.0
    return 1000.0


def main():
    if len(sys.argv) != 2:
        print(__doc__, file=sys.stderr)
        return 2
    path = sys.argv[1]
    document, binary = read_glb(path)
    try:
        info = document["asset"]["extras"]["tutti"]
        fps, frames = info["fps"], info["frames"]
    except (KeyError, TypeError):
        fail(path, "no asset.extras.tutti (fps, frames): not a tutti export", 2)
    # The performers' bodies and hands, not their instruments (rotary valves turn a quarter in a
    # press): an instrument is a model a contact touches.
    instruments = {c["part_root"] for c in document.get("extras", {}).get("tutti", {})
                   .get("contacts", [])}
    posed = Posed(document, binary)
    root_of = {}
    for index in range(len(posed.nodes)):
        top = index
        while top in posed.parent:
            top = posed.parent[top]
        root_of[index] = posed.nodes[top].get("name", "")
    results = []
    for (node, path_kind), channel in posed.channels.items():
        if path_kind != "rotation" or root_of[node] in instruments:
            continue
        name = posed.nodes[node].get("name", f"node {node}")
        fastest, at = 0.0, 0.0
        previous = channel.at(0.0)
        for k in range(1, frames):
            q = channel.at(k / fps)
            dot = min(1.0, abs(sum(a * b for a, b in zip(q, previous))))
            speed = math.degrees(2.0 * math.acos(dot)) * fps
            if speed > fastest:
                fastest, at = speed, k / fps
            previous = q
        results.append((fastest / limit_for(root_of[node], name), fastest, at, root_of[node], name,
                        limit_for(root_of[node], name)))
    results.sort(reverse=True)
    print(f"{path}: {len(results)} turning nodes over {frames} frames at {fps} fps; fastest for "
          "their limits:")
    for share, speed, at, root, name, limit in results[:5]:
        print(f"  {root}/{name}: {speed:.1f} deg/s at {at:.3f} s (limit {limit:.0f})")
    over = [r for r in results if r[0] > 1.0]
    for share, speed, at, root, name, limit in over:
        print(f"FAIL: {root}/{name} turns {speed:.1f} deg/s at {at:.3f} s, over {limit:.0f}")
    return 1 if over else 0


if __name__ == "__main__":
    sys.exit(main())
