# SPDX-License-Identifier: MIT
# Blender side of scripts/blender-comparison: imports tutti's exported performance (.glb), puts
# the scene file's camera and key light in, renders frames with one engine and prints
# "ENGINE ms_per_frame frames" (the import and the first, warm-up frame not counted).
#   blender -b --python scripts/blender_comparison.py -- GLB SCENE_JSON CAMERA ENGINE FRAMES W H OUT
import json
import math
import sys
import time

import bpy
import mathutils
import numpy

# Debian 12's Blender 3.4 importer still says numpy.bool, which Debian's numpy 1.24 removed
# (the same shim as tests/export/blender_import.py).
if not hasattr(numpy, "bool"):
    numpy.bool = bool

glb, scene_json, camera_name, engine, frames, width, height, out = sys.argv[sys.argv.index("--") + 1:]
frames, width, height = int(frames), int(width), int(height)

bpy.ops.wm.read_factory_settings(use_empty=True)
bpy.ops.import_scene.gltf(filepath=glb)
scene = bpy.context.scene


def blender_axes(v):  # glTF (+Y up) to Blender (+Z up), as the importer converts
    return mathutils.Vector((v[0], -v[2], v[1]))


with open(scene_json) as f:
    description = json.load(f)
camera = next(c for c in description["cameras"] if c["name"] == camera_name)
data = bpy.data.cameras.new("tutti_camera")
data.sensor_fit = "VERTICAL"
data.angle = math.radians(camera.get("fov_deg", 40.0))
camera_object = bpy.data.objects.new("tutti_camera", data)
scene.collection.objects.link(camera_object)
position = blender_axes(camera["position_m"])
camera_object.location = position
look = blender_axes(camera["target_m"]) - position
camera_object.rotation_euler = look.to_track_quat("-Z", "Y").to_euler()
scene.camera = camera_object

key = description.get("lights", {}).get("key", {"direction": [-0.4, -1, -0.5], "intensity": 3.0})
sun = bpy.data.lights.new("key", type="SUN")
sun.energy = key.get("intensity", 3.0)
sun_object = bpy.data.objects.new("key", sun)
scene.collection.objects.link(sun_object)
sun_object.rotation_euler = blender_axes(key["direction"]).to_track_quat("-Z", "Y").to_euler()

scene.render.engine = "BLENDER_EEVEE" if engine == "eevee" else "BLENDER_WORKBENCH"
scene.render.resolution_x = width
scene.render.resolution_y = height
scene.render.resolution_percentage = 100
scene.render.image_settings.file_format = "PNG"
start = scene.frame_start
scene.frame_set(start)
scene.render.filepath = out + "_warmup.png"
bpy.ops.render.render(write_still=True)
began = time.perf_counter()
for k in range(frames):
    scene.frame_set(start + 1 + k)
    scene.render.filepath = "%s_%04d.png" % (out, k)
    bpy.ops.render.render(write_still=True)
elapsed = time.perf_counter() - began
print("TUTTI_COMPARISON %s %.1f %d" % (engine, 1000.0 * elapsed / frames, frames))
