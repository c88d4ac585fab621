# SPDX-License-Identifier: MIT
"""Compares what Blender imported (blender_import.py's JSON) with what tutti exported (tutti
export --json): every clip became actions named after it, each spanning the exported frames;
there are armatures and shape keys. Prints a summary; exit 1 with the reasons on a mismatch."""
import json
import sys

summary = json.load(open(sys.argv[1]))
imported = json.load(open(sys.argv[2]))
last = summary["frames"] - 1
problems = []
actions = imported["actions"]
for clip in summary["clips"]:
    mine = [a for a in actions if a["name"] == clip["name"] or a["name"].startswith(clip["name"] + "_")]
    if not mine:
        problems.append(f'clip "{clip["name"]}": no action in Blender')
        continue
    ranges = sorted({tuple(a["frame_range"]) for a in mine})
    lo = min(r[0] for r in ranges)
    hi = max(r[1] for r in ranges)
    if abs(lo - 0) > 1e-3 or abs(hi - last) > 1e-3:
        problems.append(f'clip "{clip["name"]}": frames {lo:g}..{hi:g}, expected 0..{last}')
    print(f'clip "{clip["name"]}": {len(mine)} actions, {sum(a["fcurves"] for a in mine)} '
          f'f-curves, frames {lo:g}..{hi:g}')
if clip_tracks := [c["name"] for c in summary["clips"] if c["name"] not in imported["nla_tracks"]]:
    problems.append(f"no NLA track for {clip_tracks} (tracks: {imported['nla_tracks']})")
if not imported["armatures"]:
    problems.append("no armature")
for needed in ("tension", "open"):
    if needed not in imported["shape_keys"] and any(a["name"].endswith("ShapeKey") for a in actions):
        problems.append(f'no "{needed}" shape key')
print(f'blender {imported["blender"]}: {len(actions)} actions, {len(imported["armatures"])} '
      f'armatures ({", ".join(str(a["bones"]) for a in imported["armatures"])} bones), '
      f'{imported["meshes"]} meshes, shape keys {imported["shape_keys"]}')
for p in problems:
    print("error: " + p, file=sys.stderr)
sys.exit(1 if problems else 0)
