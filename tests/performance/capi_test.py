#!/usr/bin/env python3
"""The C API (tutti.h) from Python with ctypes, as a host in another language uses it.

    capi_test.py LIBTUTTI_SO SCENES_DIR

Opens the quartet, reads its performers, models, nodes and morphs, samples poses, checks that a
valve node goes down after its valve_down event and that the same t gives the same pose, reads
the events, and checks the error paths (a missing scene, a bad index, a short buffer)."""
import ctypes
import math
import os
import sys


class Trs(ctypes.Structure):
    _fields_ = [("translation", ctypes.c_float * 3), ("rotation", ctypes.c_float * 4),
                ("scale", ctypes.c_float * 3)]


class Event(ctypes.Structure):
    _fields_ = [("t_s", ctypes.c_double), ("kind", ctypes.c_int32), ("performer", ctypes.c_int32),
                ("value", ctypes.c_int32), ("reserved", ctypes.c_int32)]


class Options(ctypes.Structure):
    _fields_ = [("content_dir", ctypes.c_char_p), ("asset_dir", ctypes.c_char_p),
                ("contact_step_s", ctypes.c_double)]


OK, BAD_INPUT, INVALID_ARGUMENT = 0, 2, 4
VALVE_DOWN = 4


def load(path):
    lib = ctypes.CDLL(path)
    p, i32, f64, s = ctypes.c_void_p, ctypes.c_int32, ctypes.c_double, ctypes.c_char_p
    signatures = {
        "tutti_version": (s, []),
        "tutti_last_error": (s, []),
        "tutti_event_kind_name": (s, [i32]),
        "tutti_default_options": (None, [ctypes.POINTER(Options)]),
        "tutti_open": (i32, [s, ctypes.POINTER(Options), ctypes.POINTER(p)]),
        "tutti_close": (None, [p]),
        "tutti_start_s": (f64, [p]),
        "tutti_end_s": (f64, [p]),
        "tutti_performer_count": (i32, [p]),
        "tutti_performer_name": (s, [p, i32]),
        "tutti_performer_family": (s, [p, i32]),
        "tutti_performer_instrument": (s, [p, i32]),
        "tutti_model_count": (i32, [p]),
        "tutti_model_name": (s, [p, i32]),
        "tutti_model_performer": (i32, [p, i32]),
        "tutti_node_count": (i32, [p, i32]),
        "tutti_node_name": (s, [p, i32, i32]),
        "tutti_node_parent": (i32, [p, i32, i32]),
        "tutti_morph_count": (i32, [p, i32]),
        "tutti_morph_name": (s, [p, i32, i32]),
        "tutti_sample": (i32, [p, f64]),
        "tutti_model_root": (i32, [p, i32, ctypes.POINTER(Trs)]),
        "tutti_model_pose": (i32, [p, i32, ctypes.POINTER(Trs), i32]),
        "tutti_model_morph_weights": (i32, [p, i32, ctypes.POINTER(ctypes.c_float), i32]),
        "tutti_events": (i32, [p, f64, f64, ctypes.POINTER(Event), i32]),
    }
    for name, (restype, argtypes) in signatures.items():
        function = getattr(lib, name)
        function.restype = restype
        function.argtypes = argtypes
    return lib


def check(condition, message):
    if not condition:
        print("capi test: FAILED:", message, file=sys.stderr)
        sys.exit(1)


def main():
    lib = load(sys.argv[1])
    scenes = sys.argv[2]
    print("libtutti", lib.tutti_version().decode())

    # A missing scene: a status code and one line naming the file.
    handle = ctypes.c_void_p()
    status = lib.tutti_open(os.path.join(scenes, "no_such.json").encode(), None,
                            ctypes.byref(handle))
    message = lib.tutti_last_error().decode()
    check(status == BAD_INPUT and "no_such.json" in message and "\n" not in message,
          f"missing scene: status {status}, {message!r}")

    options = Options()
    lib.tutti_default_options(ctypes.byref(options))
    check(options.contact_step_s > 0, "default options")
    status = lib.tutti_open(os.path.join(scenes, "quartet.json").encode(), ctypes.byref(options),
                            ctypes.byref(handle))
    check(status == OK, f"open: {lib.tutti_last_error().decode()}")
    p = handle
    performers = [lib.tutti_performer_name(p, i).decode()
                  for i in range(lib.tutti_performer_count(p))]
    check(performers == ["Trumpet 1", "Trumpet 2", "Trombone 1", "Trombone 2"], performers)
    check(lib.tutti_performer_instrument(p, 0) == b"trumpet_bb", "instrument")
    check(lib.tutti_performer_name(p, 99) is None, "a performer out of range is NULL")

    models = {lib.tutti_model_name(p, m).decode(): m for m in range(lib.tutti_model_count(p))}
    horn = models["Trumpet 1 trumpet"]
    body = models["Trumpet 1"]
    check(lib.tutti_model_performer(p, horn) == 0, "the trumpet is Trumpet 1's")
    nodes = [lib.tutti_node_name(p, horn, n).decode() for n in range(lib.tutti_node_count(p, horn))]
    valve = nodes.index("valve_1")
    body_nodes = [lib.tutti_node_name(p, body, n).decode()
                  for n in range(lib.tutti_node_count(p, body))]
    check("hips" in body_nodes and "head" in body_nodes, body_nodes[:10])
    check(lib.tutti_node_parent(p, body, body_nodes.index("spine")) == body_nodes.index("hips"),
          "spine's parent is hips")
    morphs = [lib.tutti_morph_name(p, body, k).decode() for k in range(lib.tutti_morph_count(p, body))]
    check("tension" in morphs and "open" in morphs, morphs)

    # Reading before sampling is an error; a short buffer is an error.
    pose = (Trs * len(nodes))()
    check(lib.tutti_model_pose(p, horn, pose, len(nodes)) == INVALID_ARGUMENT, "pose before sample")
    check(lib.tutti_sample(p, lib.tutti_start_s(p)) == OK, "sample")
    check(lib.tutti_model_pose(p, horn, pose, len(nodes) - 1) == INVALID_ARGUMENT, "short buffer")
    check(lib.tutti_model_pose(p, horn, pose, len(nodes)) == OK, "pose")
    rest_y = pose[valve].translation[1]

    # The events: valve 1 of Trumpet 1 goes down; just after, its node is 15+ mm lower.
    total = lib.tutti_events(p, -1e9, 1e9, None, 0)
    events = (Event * total)()
    check(lib.tutti_events(p, -1e9, 1e9, events, total) == total, "events")
    kinds = {lib.tutti_event_kind_name(e.kind).decode() for e in events}
    check({"note_on", "note_off", "valve_down", "slide_arrives", "breath_start", "cue"} <= kinds,
          kinds)
    downs = [e.t_s for e in events if e.kind == VALVE_DOWN and e.performer == 0 and e.value == 1]
    check(len(downs) > 3, f"{len(downs)} valve-1 downs")
    for t in downs[:5]:
        check(lib.tutti_sample(p, t + 0.002) == OK, "sample")
        check(lib.tutti_model_pose(p, horn, pose, len(nodes)) == OK, "pose")
        check(pose[valve].translation[1] < rest_y - 0.015,
              f"valve 1 at {t:.3f} s: y {pose[valve].translation[1]:.4f} vs rest {rest_y:.4f}")

    # The same t, the same pose, whatever was sampled in between.
    def snapshot(t):
        check(lib.tutti_sample(p, t) == OK, "sample")
        out = []
        for m in range(lib.tutti_model_count(p)):
            count = lib.tutti_node_count(p, m)
            buffer = (Trs * count)()
            check(lib.tutti_model_pose(p, m, buffer, count) == OK, "pose")
            out.extend((tuple(x.translation), tuple(x.rotation)) for x in buffer)
            weights = (ctypes.c_float * max(1, lib.tutti_morph_count(p, m)))()
            check(lib.tutti_model_morph_weights(p, m, weights, len(weights)) == OK, "weights")
            out.extend(weights)
        return out
    first = snapshot(12.5)
    snapshot(30.0)
    check(snapshot(12.5) == first, "sample(12.5) twice")
    check(all(math.isfinite(v) for item in first if isinstance(item, tuple) for xs in item
              for v in xs), "finite")
    root = Trs()
    check(lib.tutti_model_root(p, body, ctypes.byref(root)) == OK, "root")
    check(lib.tutti_model_root(p, 999, ctypes.byref(root)) == INVALID_ARGUMENT, "bad model")
    check(lib.tutti_sample(p, float("nan")) == INVALID_ARGUMENT, "NaN time")
    lib.tutti_close(p)
    print(f"capi test: passed ({len(performers)} performers, {len(models)} models, "
          f"{total} events, {len(first)} values per pose)")


main()
