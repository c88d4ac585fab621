#!/usr/bin/env bash
# SPDX-License-Identifier: MIT
# `tutti export` of a shipped scene, checked by real clients:
#   1. the Khronos glTF validator (npm gltf-validator) reports zero errors;
#   2. headless Blender imports it with one action set per clip (each performer, the whole
#      scene) whose frame ranges are the exported frames, armatures with the rig's bones, and the
#      mouth shape keys.
#   3. (contacts) its extras.tutti.contacts agree with its own animation (check_contacts.py),
#      and no joint of a body turns faster than its limit in it (check_joint_speeds.py).
#   export_check.sh TUTTI VALIDATOR_DIR SCENE WORK_DIR [validate|blender|both|contacts]
set -euo pipefail
tutti="$1"
validator_dir="$2"
scene="$3"
work="$4"
what="${5:-both}"
here="$(cd "$(dirname "$0")" && pwd)"
name="$(basename "$scene" .json)"
mkdir -p "$work"
glb="$work/$name.glb"

start=$(date +%s%N)
"$tutti" export "$scene" -o "$glb" --json > "$work/$name.summary.json"
elapsed=$(( ($(date +%s%N) - start) / 1000000 ))
python3 -c 'import json, sys
s = json.load(open(sys.argv[1]))
print("export: %d bytes, %d frames at %d fps, %d of %d samples kept, clips %s in %s ms" % (
    s["bytes"], s["frames"], s["fps"], s["keys"], s["samples"],
    ", ".join(c["name"] for c in s["clips"]), sys.argv[2]))' "$work/$name.summary.json" "$elapsed"

if [ "$what" = validate ] || [ "$what" = both ]; then
  node "$here/validator/validate_gltf.mjs" "$validator_dir" "$glb" --max-warnings 0
fi

if [ "$what" = contacts ]; then
  python3 "$here/check_contacts.py" "$glb" --max-p95-mm 10
  python3 "$here/check_joint_speeds.py" "$glb"
fi

if [ "$what" = blender ] || [ "$what" = both ]; then
  fps=$(python3 -c 'import json,sys; print(json.load(open(sys.argv[1]))["fps"])' "$work/$name.summary.json")
  start=$(date +%s%N)
  if ! blender -b --factory-startup --python-exit-code 3 --python "$here/blender_import.py" -- \
      "$glb" "$fps" "$work/$name.blender.json" > "$work/$name.blender.log" 2>&1; then
    echo "error: blender could not import $glb (log: $work/$name.blender.log)" >&2
    tail -20 "$work/$name.blender.log" >&2
    exit 1
  fi
  echo "blender import: $(( ($(date +%s%N) - start) / 1000000 )) ms"
  python3 "$here/check_blender_import.py" "$work/$name.summary.json" "$work/$name.blender.json"
fi
