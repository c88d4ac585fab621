# Character fixtures made by third-party tools, at test time (issue 21): Blender's bundled Rigify
# add-on builds its human meta-rig (3 bones per finger plus palm bones), a body skinned to it is
# made of one tapered tube per bone, and Blender's own glTF exporter writes the variants below.
#
#   blender -b --factory-startup --python tests/data/characters/make_fixtures.py -- OUT_DIR
#
# Variants (OUT_DIR/<name>.glb, and a .vrm): the Rigify names as they are, and the same bones
# renamed the Mixamo way (with the "mixamorig:" namespace, without it, with a "rig_" prefix) and
# the Unreal way; in metres, or in centimetres under a 0.01 root scale (as FBX imports are); in
# the meta-rig's own A-pose or turned into a T-pose; one as VRM 1.0 (a VRMC_vrm humanoid table
# added to the exported file); one with a PNG base-colour texture (a red and cream checker, 8
# squares round each tube and 4 along it); one as Rigify's deform rig names and splits it
# ("DEF-" names, each upper arm, forearm, thigh and shin in two segments); and hands_only.glb, the
# forearms, hands and fingers alone (a pianist's hand models). Every body has the face shape keys
# mouthPucker and jawOpen (ARKit's names) on its head. Writes OUT_DIR/fixtures.json: every file with what it
# should be.
import json
import math
import os
import struct
import sys

import addon_utils
import bmesh
import bpy
from mathutils import Matrix, Vector

OUT = sys.argv[sys.argv.index("--") + 1]
os.makedirs(OUT, exist_ok=True)

FINGERS = {"f_index": "Index", "f_middle": "Middle", "f_ring": "Ring", "f_pinky": "Pinky"}


def side_of(name):
    return name[-1] if name.endswith((".L", ".R")) else ""


def mixamo_name(name):
    body = {"spine": "Hips", "spine.001": "Spine", "spine.002": "Spine1", "spine.003": "Spine2",
            "spine.004": "Neck", "spine.005": "Neck1", "spine.006": "Head"}
    if name in body:
        return body[name]
    side = {"L": "Left", "R": "Right"}.get(side_of(name), "")
    base = name[:-2] if side else name
    limbs = {"shoulder": "Shoulder", "upper_arm": "Arm", "forearm": "ForeArm", "hand": "Hand",
             "thigh": "UpLeg", "shin": "Leg", "foot": "Foot", "toe": "ToeBase",
             "breast": "Breast", "pelvis": "Pelvis", "heel.02": "Heel"}
    if base in limbs:
        return side + limbs[base]
    if base.startswith("thumb."):
        return side + "HandThumb" + str(int(base[-2:]))
    if base.startswith("palm."):
        return side + "HandPalm" + str(int(base[-2:]))
    finger, number = base.split(".")
    return side + "Hand" + FINGERS[finger] + str(int(number))


def unreal_name(name):
    body = {"spine": "pelvis", "spine.001": "spine_01", "spine.002": "spine_02",
            "spine.003": "spine_03", "spine.004": "neck_01", "spine.005": "neck_02",
            "spine.006": "head"}
    if name in body:
        return body[name]
    side = {"L": "_l", "R": "_r"}.get(side_of(name), "")
    base = name[:-2] if side else name
    limbs = {"shoulder": "clavicle", "upper_arm": "upperarm", "forearm": "lowerarm",
             "hand": "hand", "thigh": "thigh", "shin": "calf", "foot": "foot", "toe": "ball",
             "breast": "breast", "pelvis": "pelvis_side", "heel.02": "heel"}
    if base in limbs:
        return limbs[base] + side
    if base.startswith("thumb."):
        return "thumb_" + base[-2:] + side
    # UE5: the palm bones are the fingers' metacarpals.
    palm_finger = {"palm.01": "index", "palm.02": "middle", "palm.03": "ring", "palm.04": "pinky"}
    if base in palm_finger:
        return palm_finger[base] + "_metacarpal" + side
    finger, number = base.split(".")
    return FINGERS[finger].lower() + "_" + number + side


VRM_BONES = {"spine": "hips", "spine.001": "spine", "spine.002": "chest", "spine.003": "upperChest",
             "spine.004": "neck", "spine.006": "head"}
for s, side in (("L", "left"), ("R", "right")):
    VRM_BONES.update({f"shoulder.{s}": side + "Shoulder", f"upper_arm.{s}": side + "UpperArm",
                      f"forearm.{s}": side + "LowerArm", f"hand.{s}": side + "Hand",
                      f"thigh.{s}": side + "UpperLeg", f"shin.{s}": side + "LowerLeg",
                      f"foot.{s}": side + "Foot", f"toe.{s}": side + "Toes",
                      f"thumb.01.{s}": side + "ThumbMetacarpal",
                      f"thumb.02.{s}": side + "ThumbProximal", f"thumb.03.{s}": side + "ThumbDistal"})
    for finger, vrm in (("f_index", "Index"), ("f_middle", "Middle"), ("f_ring", "Ring"),
                        ("f_pinky", "Little")):
        for number, joint in (("01", "Proximal"), ("02", "Intermediate"), ("03", "Distal")):
            VRM_BONES[f"{finger}.{number}.{s}"] = side + vrm + joint


def split_limbs(rig):
    """Each upper arm, forearm, thigh and shin in two, as Rigify's deform rig has them
    ("forearm.L" and "forearm.L.001" under it)."""
    bpy.context.view_layer.objects.active = rig
    bpy.ops.object.mode_set(mode="EDIT")
    bones = rig.data.edit_bones
    for bone in bones:
        bone.select = bone.select_head = bone.select_tail = False
    for limb in ("upper_arm", "forearm", "thigh", "shin"):
        for side in ("L", "R"):
            bone = bones[limb + "." + side]
            bone.select = bone.select_head = bone.select_tail = True
    bpy.ops.armature.subdivide(number_cuts=1)
    bpy.ops.object.mode_set(mode="OBJECT")


def hands_only(rig):
    """Only the forearms, hands and fingers (a pianist's hand models): the rest of the skeleton
    goes and the forearms become roots."""
    bpy.context.view_layer.objects.active = rig
    bpy.ops.object.mode_set(mode="EDIT")
    bones = rig.data.edit_bones
    keep = set()
    for side in ("L", "R"):
        forearm = bones["forearm." + side]
        keep.add(forearm.name)
        keep.update(bone.name for bone in forearm.children_recursive)
    for bone in list(bones):
        if bone.name not in keep:
            bones.remove(bone)
    for side in ("L", "R"):
        bones["forearm." + side].parent = None
    bpy.ops.object.mode_set(mode="OBJECT")


def fresh_rig(pose):
    bpy.ops.wm.read_factory_settings(use_empty=True)
    addon_utils.enable("rigify", default_set=True)
    bpy.ops.object.armature_human_metarig_add()
    rig = bpy.context.object
    rig.name = "Armature"
    bpy.ops.object.mode_set(mode="EDIT")
    bones = rig.data.edit_bones
    # A body rig: the face rig's 91 bones go.
    for bone in list(bones["face"].children_recursive) + [bones["face"]]:
        bones.remove(bone)
    if pose == "T":
        for side, sign in (("L", 1.0), ("R", -1.0)):
            upper = bones["upper_arm." + side]
            pivot = upper.head.copy()
            turn = (upper.tail - upper.head).normalized().rotation_difference(Vector((sign, 0, 0)))
            matrix = Matrix.Translation(pivot) @ turn.to_matrix().to_4x4() @ Matrix.Translation(-pivot)
            # Every new position from the old ones: a connected child's head is its parent's
            # tail, so transforming bone by bone would turn it twice.
            chain = [upper] + list(upper.children_recursive)
            old = {bone.name: (bone.head.copy(), bone.tail.copy()) for bone in chain}
            for bone in chain:
                bone.head = matrix @ old[bone.name][0]
                bone.tail = matrix @ old[bone.name][1]
    bpy.ops.object.mode_set(mode="OBJECT")
    return rig


def checker_material():
    """A material whose base colour is a 64 x 64 PNG checker (red and cream, 8 x 8 squares)."""
    image = bpy.data.images.new("checker", 64, 64)
    pixels = []
    for y in range(64):
        for x in range(64):
            red = ((x // 8) + (y // 8)) % 2 == 0
            pixels += [0.8, 0.1, 0.1, 1.0] if red else [0.95, 0.9, 0.75, 1.0]
    image.pixels = pixels
    image.file_format = "PNG"
    image.pack()
    material = bpy.data.materials.new("checker")
    material.use_nodes = True
    nodes = material.node_tree.nodes
    texture = nodes.new("ShaderNodeTexImage")
    texture.image = image
    material.node_tree.links.new(texture.outputs["Color"],
                                 nodes["Principled BSDF"].inputs["Base Color"])
    return material


def skinned_body(rig, textured=False):
    """One tapered 8-sided tube per bone, every vertex weighted 1 to its bone; with `textured`,
    UVs round (u) and along (v) each tube and the checker material."""
    mesh = bpy.data.meshes.new("body")
    body = bpy.data.objects.new("body", mesh)
    bpy.context.collection.objects.link(body)
    bm = bmesh.new()
    uv_layer = bm.loops.layers.uv.new("UVMap") if textured else None
    groups = {}
    for bone in rig.data.bones:
        head, tail = bone.head_local, bone.tail_local
        axis = tail - head
        length = axis.length
        radius = max(0.006, min(0.09, 0.2 * length))
        if bone.name.startswith("spine"):
            radius = 0.12 if bone.name != "spine.006" else 0.09
        u = axis.orthogonal().normalized()
        v = axis.cross(u).normalized()
        rings = []
        for centre, r in ((head, radius), (tail, radius * 0.85)):
            ring = []
            for k in range(8):
                a = 2 * math.pi * k / 8
                ring.append(bm.verts.new(centre + r * (math.cos(a) * u + math.sin(a) * v)))
            rings.append(ring)
        for k in range(8):
            face = bm.faces.new((rings[0][k], rings[0][(k + 1) % 8], rings[1][(k + 1) % 8],
                                 rings[1][k]))
            if uv_layer is not None:
                for loop, uv in zip(face.loops, ((k / 8, 0.0), ((k + 1) / 8, 0.0),
                                                 ((k + 1) / 8, 0.5), (k / 8, 0.5))):
                    loop[uv_layer].uv = uv
        groups[bone.name] = [vert for ring in rings for vert in ring]
    bm.verts.index_update()
    indices = {name: [vert.index for vert in verts] for name, verts in groups.items()}
    bm.to_mesh(mesh)
    bm.free()
    for name, vertex_indices in indices.items():
        body.vertex_groups.new(name=name).add(vertex_indices, 1.0, "REPLACE")
    body.parent = rig
    body.modifiers.new("Armature", "ARMATURE").object = rig
    if textured:
        mesh.materials.append(checker_material())
    # Face shape keys by their ARKit names: the head tube's lower ring drawn in (pucker) and
    # dropped (jaw open).
    head = "spine.006"
    if head in indices:
        body.shape_key_add(name="Basis")
        centre = rig.data.bones[head].head_local
        for name, move in (("mouthPucker", lambda co: (centre - co) * 0.3 * Vector((1, 0, 1))),
                           ("jawOpen", lambda co: Vector((0, 0, -0.02)))):
            key = body.shape_key_add(name=name)
            for index in indices[head][:8]:
                co = mesh.vertices[index].co
                key.data[index].co = co + move(co)
    return body


def to_centimetres(rig, body):
    """Bones and body 100 times larger, under a 0.01 scale on the armature (an FBX import)."""
    bpy.ops.object.select_all(action="DESELECT")
    for obj in (rig, body):
        obj.select_set(True)
    bpy.context.view_layer.objects.active = rig
    rig.scale = (100.0, 100.0, 100.0)
    bpy.ops.object.transform_apply(location=False, rotation=False, scale=True)
    rig.scale = (0.01, 0.01, 0.01)


def export(path):
    bpy.ops.export_scene.gltf(filepath=path, export_format="GLB", export_yup=True)


def add_vrm_table(glb_path, vrm_path):
    data = open(glb_path, "rb").read()
    json_length = struct.unpack_from("<I", data, 12)[0]
    doc = json.loads(data[20:20 + json_length])
    bones = {}
    for index, node in enumerate(doc["nodes"]):
        if node.get("name") in VRM_BONES:
            bones[VRM_BONES[node["name"]]] = {"node": index}
    doc.setdefault("extensionsUsed", []).append("VRMC_vrm")
    doc.setdefault("extensions", {})["VRMC_vrm"] = {
        "specVersion": "1.0", "meta": {"name": "tutti fixture", "licenseUrl": "https://vrm.dev/licenses/1.0/"},
        "humanoid": {"humanBones": bones}}
    text = json.dumps(doc, separators=(",", ":")).encode()
    text += b" " * ((4 - len(text) % 4) % 4)
    rest = data[20 + json_length:]
    out = struct.pack("<III", 0x46546C67, 2, 12 + 8 + len(text) + len(rest))
    out += struct.pack("<II", len(text), 0x4E4F534A) + text + rest
    open(vrm_path, "wb").write(out)


VARIANTS = [
    # name, naming, units, pose
    ("rigify_a", None, "m", "A"),
    ("rigify_t", None, "m", "T"),
    ("mixamo_ns_cm_a", lambda n: "mixamorig:" + mixamo_name(n), "cm", "A"),
    ("mixamo_plain_t", mixamo_name, "m", "T"),
    ("mixamo_rig_prefix_a", lambda n: "rig_" + mixamo_name(n), "m", "A"),
    ("unreal_cm_t", unreal_name, "cm", "T"),
    ("rigify_a_textured", None, "m", "A"),
    ("rigify_def_split_a", lambda n: "DEF-" + n, "m", "A"),
]

listing = []
for name, naming, units, pose in VARIANTS:
    rig = fresh_rig(pose)
    if "_split" in name:
        split_limbs(rig)
    body = skinned_body(rig, textured=name.endswith("_textured"))
    expected = {}
    for bone in rig.data.bones:
        expected[bone.name] = naming(bone.name) if naming else bone.name
    if naming:
        for bone in rig.data.bones:
            bone.name = expected[bone.name]  # renames the body's vertex groups too
    if units == "cm":
        to_centimetres(rig, body)
    path = os.path.join(OUT, name + ".glb")
    export(path)
    listing.append({"file": name + ".glb", "pose": pose, "units": units,
                    "textured": name.endswith("_textured"),
                    "names": {rigify: ours for rigify, ours in expected.items()}})
    if name == "rigify_a":
        add_vrm_table(path, os.path.join(OUT, "rigify_a_vrm1.vrm"))
        listing.append({"file": "rigify_a_vrm1.vrm", "pose": pose, "units": units, "vrm": True,
                        "names": {rigify: rigify for rigify in expected}})

# A pianist's hand models alone (not in fixtures.json: not a character).
rig = fresh_rig("A")
hands_only(rig)
skinned_body(rig)
export(os.path.join(OUT, "hands_only.glb"))

with open(os.path.join(OUT, "fixtures.json"), "w") as f:
    json.dump(listing, f, indent=1)
print("fixtures: wrote", len(listing), "files to", OUT)
