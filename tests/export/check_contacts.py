#!/usr/bin/env python3
# SPDX-License-Identifier: MIT
"""Checks a `tutti export` .glb's contacts (root extras.tutti.contacts) against its own animation,
with none of tutti's code: the file is read, the whole-scene clip sampled (LINEAR and STEP
samplers) and every node posed by forward kinematics here.

  check_contacts.py FILE.glb [--max-p95-mm 10] [--min-contacts 1]

- Each contact span's point, taken from its part node's frame to the world, lies within
  --max-p95-mm (95th percentile over every span's frames) of its body node.
- Every piano key or organ pedal press (a node key_<midi> or pedal_<midi> turned more than
  0.05 deg: tutti's keys and pedals rest unturned) and every valve press (a node valve_<n> moved more than 0.2 mm off its highest
  place in the clip) at an exported frame is
  covered by a span of a contact on that node.
- A contact's point on a pedal lies on the pedal's top (within 6 mm of it), over its mesh: a
  toe that presses a pedal is on it, not beside or above it.
Prints the figures; exits 1 on a failed check, 2 on a file it cannot read.
"""

import argparse
import bisect
import json
import math
import re
import struct
import sys


def fail(path, message, code=2):
    print(f"{path}: {message}", file=sys.stderr)
    sys.exit(code)


def read_glb(path):
    try:
        data = open(path, "rb").read()
    except OSError as error:
        fail(path, f"cannot read: {error.strerror}")
    if len(data) < 20 or data[:4] != b"glTF":
        fail(path, "not a binary glTF file")
    json_length, json_type = struct.unpack_from("<I4s", data, 12)
    if json_type != b"JSON":
        fail(path, "first chunk is not JSON")
    document = json.loads(data[20:20 + json_length])
    offset = 20 + json_length
    binary = b""
    if offset + 8 <= len(data):
        bin_length, bin_type = struct.unpack_from("<I4s", data, offset)
        if bin_type == b"BIN\x00":
            binary = data[offset + 8:offset + 8 + bin_length]
    return document, binary


COMPONENTS = {"SCALAR": 1, "VEC2": 2, "VEC3": 3, "VEC4": 4, "MAT4": 16}


def read_accessor(document, binary, index):
    accessor = document["accessors"][index]
    if accessor["componentType"] != 5126:
        raise ValueError(f"accessor {index}: only float accessors are read")
    view = document["bufferViews"][accessor["bufferView"]]
    width = COMPONENTS[accessor["type"]]
    stride = view.get("byteStride", 4 * width)
    start = view.get("byteOffset", 0) + accessor.get("byteOffset", 0)
    values = []
    for i in range(accessor["count"]):
        values.append(struct.unpack_from(f"<{width}f", binary, start + i * stride))
    return values


# Quaternions (x, y, z, w) and 4x4 matrices as row-major lists of lists.
def slerp(a, b, u):
    dot = sum(x * y for x, y in zip(a, b))
    if dot < 0.0:
        b, dot = tuple(-x for x in b), -dot
    if dot > 0.9995:
        q = tuple(x + (y - x) * u for x, y in zip(a, b))
    else:
        theta = math.acos(min(1.0, dot))
        s = math.sin(theta)
        wa, wb = math.sin((1 - u) * theta) / s, math.sin(u * theta) / s
        q = tuple(wa * x + wb * y for x, y in zip(a, b))
    n = math.sqrt(sum(x * x for x in q))
    return tuple(x / n for x in q)


def trs_matrix(t, r, s):
    x, y, z, w = r
    rot = [
        [1 - 2 * (y * y + z * z), 2 * (x * y - z * w), 2 * (x * z + y * w)],
        [2 * (x * y + z * w), 1 - 2 * (x * x + z * z), 2 * (y * z - x * w)],
        [2 * (x * z - y * w), 2 * (y * z + x * w), 1 - 2 * (x * x + y * y)],
    ]
    return [[rot[i][0] * s[0], rot[i][1] * s[1], rot[i][2] * s[2], t[i]] for i in range(3)] + [
        [0.0, 0.0, 0.0, 1.0]]


def mat_mul(a, b):
    return [[sum(a[i][k] * b[k][j] for k in range(4)) for j in range(4)] for i in range(4)]


def transform_point(m, p):
    return [m[i][0] * p[0] + m[i][1] * p[1] + m[i][2] * p[2] + m[i][3] for i in range(3)]


class Channel:
    def __init__(self, times, values, interpolation, path):
        self.times, self.values, self.interpolation, self.path = times, values, interpolation, path

    def at(self, t):
        times = self.times
        if t <= times[0]:
            return self.values[0]
        if t >= times[-1]:
            return self.values[-1]
        k = bisect.bisect_right(times, t) - 1
        if self.interpolation == "STEP":
            return self.values[k]
        u = (t - times[k]) / (times[k + 1] - times[k])
        a, b = self.values[k], self.values[k + 1]
        if self.path == "rotation":
            return slerp(a, b, u)
        return tuple(x + (y - x) * u for x, y in zip(a, b))


class Posed:
    """The file's nodes posed by its whole-scene clip (its last animation)."""

    def __init__(self, document, binary):
        self.nodes = document["nodes"]
        self.parent = {}
        for i, node in enumerate(self.nodes):
            for child in node.get("children", []):
                self.parent[child] = i
        self.channels = {}
        animations = document.get("animations", [])
        if animations:
            clip = animations[-1]
            for channel in clip["channels"]:
                path = channel["target"]["path"]
                if path == "weights":
                    continue
                sampler = clip["samplers"][channel["sampler"]]
                times = [v[0] for v in read_accessor(document, binary, sampler["input"])]
                values = read_accessor(document, binary, sampler["output"])
                self.channels[(channel["target"]["node"], path)] = Channel(
                    times, values, sampler.get("interpolation", "LINEAR"), path)
        self.cache_time = None
        self.cache = {}

    def local(self, node, path, t):
        channel = self.channels.get((node, path))
        if channel is not None:
            return channel.at(t)
        rest = {"translation": (0.0, 0.0, 0.0), "rotation": (0.0, 0.0, 0.0, 1.0),
                "scale": (1.0, 1.0, 1.0)}[path]
        return tuple(self.nodes[node].get(path, rest))

    def world(self, node, t):
        if t != self.cache_time:
            self.cache_time, self.cache = t, {}
        if node in self.cache:
            return self.cache[node]
        m = trs_matrix(self.local(node, "translation", t), self.local(node, "rotation", t),
                       self.local(node, "scale", t))
        if node in self.parent:
            m = mat_mul(self.world(self.parent[node], t), m)
        self.cache[node] = m
        return m


def percentile(values, q):
    if not values:
        return 0.0
    ordered = sorted(values)
    return ordered[min(len(ordered) - 1, int(math.ceil(q * len(ordered))) - 1)]


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("glb")
    parser.add_argument("--max-p95-mm", type=float, default=10.0)
    parser.add_argument("--min-contacts", type=int, default=1)
    args = parser.parse_args()
    document, binary = read_glb(args.glb)
    try:
        contacts = document["extras"]["tutti"]["contacts"]
        info = document["asset"]["extras"]["tutti"]
        fps, frames = info["fps"], info["frames"]
    except (KeyError, TypeError):
        fail(args.glb, "no extras.tutti.contacts (or asset.extras.tutti) in the file", 1)
    posed = Posed(document, binary)
    frame_times = [k / fps for k in range(frames)]
    eps = 0.25 / fps

    distances_mm = []
    worst = (0.0, None, None)
    covered = {}  # part node -> list of (from, to)
    for contact in contacts:
        body, part = contact["body_node_index"], contact["part_node_index"]
        for name, index in (("body_node", body), ("part_node", part)):
            if self_name := posed.nodes[index].get("name"):
                if self_name != contact[name]:
                    fail(args.glb, f"{contact[name]}: node {index} is named {self_name}", 1)
        for span in contact["spans"]:
            covered.setdefault(part, []).append((span["from_s"], span["to_s"]))
            k0 = bisect.bisect_left(frame_times, span["from_s"] - eps)
            k1 = bisect.bisect_right(frame_times, span["to_s"] + eps)
            for t in frame_times[k0:k1]:
                at = transform_point(posed.world(part, t), span["part_point_m"])
                tip = transform_point(posed.world(body, t), (0.0, 0.0, 0.0))
                d = 1000.0 * math.dist(at, tip)
                distances_mm.append(d)
                if d > worst[0]:
                    worst = (d, t, f'{contact["body_root"]}/{contact["body_node"]} on '
                                   f'{contact["part_root"]}/{contact["part_node"]}')

    # Presses the animation shows, and whether a span covers each.
    presses = uncovered = 0
    first_uncovered = None
    for (node, path), channel in sorted(posed.channels.items()):
        name = posed.nodes[node].get("name", "")
        if path == "rotation" and re.fullmatch(r"(key|pedal)_\d+", name):
            rest = (0.0, 0.0, 0.0, 1.0)  # tutti's piano keys rest unturned

            def pressed(t, channel=channel, rest=rest):
                q = channel.at(t)
                dot = min(1.0, abs(sum(x * y for x, y in zip(q, rest))))
                return math.degrees(2.0 * math.acos(dot)) > 0.05
        elif path == "translation" and re.fullmatch(r"valve_\d+", name):
            top = max(channel.values, key=lambda v: v[1])

            def pressed(t, channel=channel, top=top):
                return 1000.0 * math.dist(channel.at(t), top) > 0.2
        else:
            continue
        spans = covered.get(node, [])
        for t in frame_times:
            if not pressed(t):
                continue
            presses += 1
            if not any(a - eps <= t <= b + eps for a, b in spans):
                uncovered += 1
                if first_uncovered is None:
                    first_uncovered = f"{name} (node {node}) at {t:.3f} s"

    # Points on pedals: on the pedal's top face, inside its outline (the mesh's bounds).
    off_pedal = []
    for contact in contacts:
        node = posed.nodes[contact["part_node_index"]]
        if not re.fullmatch(r"pedal_\d+", node.get("name", "")) or "mesh" not in node:
            continue
        position = document["meshes"][node["mesh"]]["primitives"][0]["attributes"]["POSITION"]
        low, high = document["accessors"][position]["min"], document["accessors"][position]["max"]
        for span in contact["spans"]:
            x, y, z = span["part_point_m"]
            miss = max(low[0] - x, x - high[0], low[2] - z, z - high[2], 0.0)
            miss = max(miss, abs(y - high[1]))
            if 1000.0 * miss > 6.0:
                off_pedal.append(f'{contact["body_node"]} on {contact["part_node"]} at '
                                 f'{span["from_s"]:.3f} s: {1000.0 * miss:.1f} mm off its top')
    pedal_spans = sum(len(c["spans"]) for c in contacts if c["part_node"].startswith("pedal_"))

    spans = sum(len(c["spans"]) for c in contacts)
    print(f"{args.glb}: {len(contacts)} contacts, {spans} spans, {len(distances_mm)} span frames; "
          f"point to body node: median {percentile(distances_mm, 0.5):.2f} mm, "
          f"p95 {percentile(distances_mm, 0.95):.2f} mm, max {worst[0]:.2f} mm"
          + (f" ({worst[2]} at {worst[1]:.3f} s)" if worst[2] else ""))
    print(f"pressed key and valve frames: {presses}, not covered by a span: {uncovered}"
          + (f" (first: {first_uncovered})" if first_uncovered else ""))
    if pedal_spans:
        print(f"pedal spans: {pedal_spans}, off the pedal's top: {len(off_pedal)}"
              + (f" (first: {off_pedal[0]})" if off_pedal else ""))
    ok = True
    if off_pedal:
        print("FAIL: a toe's point off its pedal")
        ok = False
    if len(contacts) < args.min_contacts:
        print(f"FAIL: {len(contacts)} contacts, at least {args.min_contacts} expected")
        ok = False
    if percentile(distances_mm, 0.95) > args.max_p95_mm:
        print(f"FAIL: p95 above {args.max_p95_mm} mm")
        ok = False
    if uncovered:
        print("FAIL: a press without a contact")
        ok = False
    return 0 if ok else 1


if __name__ == "__main__":
    sys.exit(main())
