#!/usr/bin/env bash
# SPDX-License-Identifier: MIT
# `tutti export` of a scene whose player is a textured character (the Blender fixture
# rigify_a_textured.glb, tests/data/characters/make_fixtures.py): the Khronos validator reports
# zero errors and zero warnings, and the file carries the character's PNG, its texture, sampler
# and UVs.
#   textured_export_check.sh TUTTI VALIDATOR_DIR SOURCE_DIR WORK_DIR
set -euo pipefail
tutti="$1"
validator_dir="$2"
source_dir="$3"
work="$4"
here="$(cd "$(dirname "$0")" && pwd)"
rm -rf "$work"
mkdir -p "$work"
blender -b --factory-startup --python "$source_dir/tests/data/characters/make_fixtures.py" -- \
  "$work" > "$work/blender.log" 2>&1
python3 - "$source_dir" "$work" <<'PY'
import json, sys
source, work = sys.argv[1], sys.argv[2]
scene = json.load(open(source + "/content/scenes/quartet.json"))
scene["music"] = source + "/content/music/quartet.musicxml"
player = scene["performers"][0]
player["character"] = "rigify_a_textured.glb"
scene["performers"] = [player]
scene.pop("shots", None)
scene["output"]["end_s"] = 4
json.dump(scene, open(work + "/textured.json", "w"), indent=1)
PY
bash "$here/export_check.sh" "$tutti" "$validator_dir" "$work/textured.json" "$work" validate
python3 - "$work/textured.glb" <<'PY'
import json, struct, sys
data = open(sys.argv[1], "rb").read()
length = struct.unpack_from("<I", data, 12)[0]
doc = json.loads(data[20:20 + length])
images = doc.get("images", [])
assert any(i.get("mimeType") == "image/png" for i in images), "no PNG image in the export"
textured = [m for m in doc["materials"] if "baseColorTexture" in m.get("pbrMetallicRoughness", {})]
assert textured, "no material with a base colour texture"
uvs = [p for mesh in doc["meshes"] for p in mesh["primitives"] if "TEXCOORD_0" in p["attributes"]]
assert uvs, "no primitive with TEXCOORD_0"
print("textured export: %d image(s), %d textured material(s), %d primitive(s) with UVs"
      % (len(images), len(textured), len(uvs)))
PY
