# SPDX-License-Identifier: MIT
# Imports a .glb into an empty Blender scene (run headless: blender -b --factory-startup
# --python blender_import.py -- FILE.glb FPS OUT.json) and writes what Blender made of it: the
# actions with their frame ranges, the NLA tracks, armatures with their bones, meshes and shape
# keys. The scene's frame rate is set to FPS first, so seconds become the same frames as in tutti.
import json
import sys

import bpy
import numpy

# Debian 12's Blender 3.4 importer still says numpy.bool, which Debian's numpy 1.24 removed
# (io_scene_gltf2/blender/imp/gltf2_blender_mesh.py); the alias meant the builtin bool.
if not hasattr(numpy, "bool"):
    numpy.bool = bool

args = sys.argv[sys.argv.index("--") + 1:]
path, fps, out = args[0], int(args[1]), args[2]

bpy.ops.wm.read_factory_settings(use_empty=True)
bpy.context.scene.render.fps = fps
bpy.context.scene.render.fps_base = 1.0
result = {"blender": bpy.app.version_string}
try:
    bpy.ops.import_scene.gltf(filepath=path)
except Exception as error:  # the importer's own message, on one line
    result["error"] = " ".join(str(error).split())
    json.dump(result, open(out, "w"), indent=1)
    sys.exit(1)

result["actions"] = sorted(
    ({"name": a.name, "frame_range": [a.frame_range[0], a.frame_range[1]], "fcurves": len(a.fcurves)}
     for a in bpy.data.actions), key=lambda a: a["name"])
result["nla_tracks"] = sorted({t.name for o in bpy.data.objects if o.animation_data
                               for t in o.animation_data.nla_tracks} |
                              {t.name for k in bpy.data.shape_keys if k.animation_data
                               for t in k.animation_data.nla_tracks})
result["armatures"] = sorted(
    ({"name": o.name, "bones": len(o.data.bones), "bone_names": sorted(b.name for b in o.data.bones)}
     for o in bpy.data.objects if o.type == "ARMATURE"), key=lambda a: a["name"])
result["objects"] = len(bpy.data.objects)
result["meshes"] = len(bpy.data.meshes)
result["shape_keys"] = sorted({b.name for k in bpy.data.shape_keys for b in k.key_blocks})
json.dump(result, open(out, "w"), indent=1)
