#!/usr/bin/env python3
# SPDX-License-Identifier: MIT
"""The C API (tutti.h) from Python with ctypes, as a host in another language uses it.

    capi_test.py LIBTUTTI_SO SCENES_DIR

Opens the quartet, reads its performers, models, nodes and morphs, samples poses, checks that a
valve node goes down after its valve_down event and that the same t gives the same pose, reads
the events, and checks the error paths (a missing scene, a bad index, a short buffer). Then the
lasting surface: version numbers, event kinds by name, options with their struct_size, every
failing call's message, all models' poses in one call, and a piece of music opened directly.
Last the contacts (tutti_contacts) and four threads sampling one performance in contexts of
their own (tutti_context_*)."""
import ctypes
import math
import os
import sys
import tempfile
import threading


class Trs(ctypes.Structure):
    _fields_ = [("translation", ctypes.c_float * 3), ("rotation", ctypes.c_float * 4),
                ("scale", ctypes.c_float * 3)]


class Event(ctypes.Structure):
    _fields_ = [("t_s", ctypes.c_double), ("kind", ctypes.c_int32), ("performer", ctypes.c_int32),
                ("value", ctypes.c_int32), ("reserved", ctypes.c_int32)]


class Options(ctypes.Structure):
    _fields_ = [("struct_size", ctypes.c_uint32),
                ("content_dir", ctypes.c_char_p), ("asset_dir", ctypes.c_char_p),
                ("contact_step_s", ctypes.c_double), ("contact_fps", ctypes.c_double)]


class Contact(ctypes.Structure):
    _fields_ = [("from_s", ctypes.c_double), ("to_s", ctypes.c_double),
                ("performer", ctypes.c_int32), ("body_model", ctypes.c_int32),
                ("body_node", ctypes.c_int32), ("part_model", ctypes.c_int32),
                ("part_node", ctypes.c_int32), ("midi", ctypes.c_int32),
                ("part_point_m", ctypes.c_float * 3), ("reserved", ctypes.c_int32)]


OK, BAD_INPUT, INVALID_ARGUMENT = 0, 2, 4


def load(path):
    lib = ctypes.CDLL(path)
    p, i32, f64, s = ctypes.c_void_p, ctypes.c_int32, ctypes.c_double, ctypes.c_char_p
    signatures = {
        "tutti_version": (s, []),
        "tutti_version_number": (i32, []),
        "tutti_event_kind_count": (i32, []),
        "tutti_event_kind_by_name": (i32, [s]),
        "tutti_node_total": (i32, [p]),
        "tutti_node_offset": (i32, [p, i32]),
        "tutti_poses": (i32, [p, ctypes.POINTER(Trs), i32, ctypes.POINTER(Trs), i32]),
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
        "tutti_contacts": (i32, [p, f64, f64, ctypes.POINTER(Contact), i32]),
        "tutti_context_new": (i32, [p, ctypes.POINTER(p)]),
        "tutti_context_free": (None, [p]),
        "tutti_context_sample": (i32, [p, f64]),
        "tutti_context_poses": (i32, [p, ctypes.POINTER(Trs), i32, ctypes.POINTER(Trs), i32]),
        "tutti_context_morph_weights": (i32, [p, i32, ctypes.POINTER(ctypes.c_float), i32]),
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
    valve_down = lib.tutti_event_kind_by_name(b"valve_down")  # kinds by name: numbers vary
    downs = [e.t_s for e in events if e.kind == valve_down and e.performer == 0 and e.value == 1]
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
    check_lasting_surface(lib, p, scenes)
    check_contacts(lib, p, scenes)
    check_contexts(lib, p)
    lib.tutti_close(p)
    print(f"capi test: passed ({len(performers)} performers, {len(models)} models, "
          f"{total} events, {len(first)} values per pose)")


def check_lasting_surface(lib, p, scenes):
    """Version numbers, event kinds by name, struct_size, every failing call's message, the bulk
    pose call and a music file opened directly (issue 29's C surface)."""
    # The version: the string and the number agree.
    major, minor, patch = (int(x) for x in lib.tutti_version().decode().split("."))
    check(lib.tutti_version_number() == major * 10000 + minor * 100 + patch,
          f"version number {lib.tutti_version_number()} vs {lib.tutti_version().decode()}")

    # Event kinds by name, both ways; a kind or a name out of range says so.
    count = lib.tutti_event_kind_count()
    names = [lib.tutti_event_kind_name(k).decode() for k in range(count)]
    check(count >= 10 and len(set(names)) == count, names)
    check(all(lib.tutti_event_kind_by_name(n.encode()) == k for k, n in enumerate(names)), names)
    check(lib.tutti_event_kind_name(count) is None and
          str(count) in lib.tutti_last_error().decode(), "a kind out of range")
    check(lib.tutti_event_kind_by_name(b"bow_change") == -1 and
          "bow_change" in lib.tutti_last_error().decode(), "an unknown kind's name")

    # Every getter that fails sets the message (a stale message would name another call).
    lib.tutti_performer_name(p, 99)
    check("tutti_performer_name" in lib.tutti_last_error().decode(), lib.tutti_last_error())
    check(lib.tutti_node_name(p, 0, 1000000) is None, "node out of range")
    message = lib.tutti_last_error().decode()
    check("tutti_node_name" in message and "1000000" in message, message)
    check(lib.tutti_morph_name(p, 0, -1) is None and
          "tutti_morph_name" in lib.tutti_last_error().decode(), "morph out of range")
    check(lib.tutti_node_parent(p, 999, 0) == -1 and
          "model 999" in lib.tutti_last_error().decode(), "parent of a model out of range")
    check(lib.tutti_model_count(None) == -1 and "NULL" in lib.tutti_last_error().decode(),
          "a null performance")
    check(lib.tutti_events(p, float("nan"), 1.0, None, 0) == -1 and
          "NaN" in lib.tutti_last_error().decode(), "NaN event window")

    # All models' poses in one call: the same transforms as model by model.
    check(lib.tutti_sample(p, 7.25) == OK, "sample")
    models = lib.tutti_model_count(p)
    total = lib.tutti_node_total(p)
    check(total == sum(lib.tutti_node_count(p, m) for m in range(models)), "node total")
    roots = (Trs * models)()
    nodes = (Trs * total)()
    check(lib.tutti_poses(p, roots, models, nodes, total - 1) == INVALID_ARGUMENT and
          str(total) in lib.tutti_last_error().decode(), "short nodes buffer")
    check(lib.tutti_poses(p, roots, models, nodes, total) == OK, lib.tutti_last_error())
    for m in range(models):
        count = lib.tutti_node_count(p, m)
        one = (Trs * count)()
        check(lib.tutti_model_pose(p, m, one, count) == OK, "pose")
        offset = lib.tutti_node_offset(p, m)
        check(all(bytes(one[n]) == bytes(nodes[offset + n]) for n in range(count)),
              f"model {m}: bulk pose differs")
        root = Trs()
        check(lib.tutti_model_root(p, m, ctypes.byref(root)) == OK, "root")
        check(bytes(root) == bytes(roots[m]), f"model {m}: bulk root differs")
    check(lib.tutti_poses(p, None, 0, nodes, total) == OK, "nodes only")

    # Options: struct_size must be set; tutti_default_options sets it.
    options = Options()
    handle = ctypes.c_void_p()
    status = lib.tutti_open(os.path.join(scenes, "quartet.json").encode(), ctypes.byref(options),
                            ctypes.byref(handle))
    check(status == INVALID_ARGUMENT and "struct_size" in lib.tutti_last_error().decode(),
          f"options without struct_size: {status}")
    lib.tutti_default_options(ctypes.byref(options))
    check(options.struct_size == ctypes.sizeof(Options), f"struct_size {options.struct_size}")

    # A piece of music opens as `tutti render PIECE` plays it: the scene tutti drafts for it.
    music = os.path.join(scenes, "..", "music", "quintet.musicxml")
    status = lib.tutti_open(music.encode(), ctypes.byref(options), ctypes.byref(handle))
    check(status == OK, f"open quintet.musicxml: {lib.tutti_last_error().decode()}")
    families = {lib.tutti_performer_family(handle, i).decode()
                for i in range(lib.tutti_performer_count(handle))}
    check(lib.tutti_performer_count(handle) >= 5 and families == {"brass"},
          f"{lib.tutti_performer_count(handle)} performers, {families}")
    check(lib.tutti_sample(handle, 3.0) == OK, "sample the drafted scene")
    lib.tutti_close(handle)
    check(lib.tutti_open(os.path.join(scenes, "no_such.mid").encode(), None,
                         ctypes.byref(handle)) == BAD_INPUT and
          "no_such.mid" in lib.tutti_last_error().decode(), "a missing music file")
    # Broken files: one line naming the file, a status, no handle.
    with tempfile.TemporaryDirectory() as folder:
        for name, data in (("cut.mid", b"MThd\x00\x00\x00\x06\x00\x01"),
                           ("cut.musicxml", b"<?xml version='1.0'?><score-partwise><part-list>"),
                           ("cut.json", b'{"music": "x.mid", "performers": ['),
                           ("hostile.json", b'{"music": 7, "performers": "all"}')):
            path = os.path.join(folder, name)
            with open(path, "wb") as f:
                f.write(data)
            handle = ctypes.c_void_p(1)
            status = lib.tutti_open(path.encode(), None, ctypes.byref(handle))
            message = lib.tutti_last_error().decode()
            check(status == BAD_INPUT and name in message and "\n" not in message and
                  not handle.value, f"{name}: status {status}, {message!r}")
    lib.tutti_close(None)


def rotate(q, v):
    x, y, z, w = q
    tx, ty, tz = 2 * (y * v[2] - z * v[1]), 2 * (z * v[0] - x * v[2]), 2 * (x * v[1] - y * v[0])
    return (v[0] + w * tx + y * tz - z * ty, v[1] + w * ty + z * tx - x * tz,
            v[2] + w * tz + x * ty - y * tx)


def apply(trs, v):
    scaled = tuple(trs.scale[k] * v[k] for k in range(3))
    r = rotate(tuple(trs.rotation), scaled)
    return tuple(r[k] + trs.translation[k] for k in range(3))


def world_point(lib, p, roots, nodes, model, node, point):
    """A point in node's frame to the stage, by the poses tutti_poses gave (forward kinematics
    here: the parent chain, then the model's root)."""
    offset = lib.tutti_node_offset(p, model)
    v = tuple(point)
    while node >= 0:
        v = apply(nodes[offset + node], v)
        node = lib.tutti_node_parent(p, model, node)
    return apply(roots[model], v)


def check_contexts(lib, p):
    """Sampling from many threads: four Python threads (ctypes lets go of the GIL in each call),
    each with its own context, pose the quartet at different times at once and get the bytes
    tutti_sample and tutti_poses give on one thread."""
    models, total = lib.tutti_model_count(p), lib.tutti_node_total(p)
    body = next(m for m in range(models) if lib.tutti_model_name(p, m) == b"Trumpet 1")
    morphs = lib.tutti_morph_count(p, body)
    times = [lib.tutti_start_s(p) + 0.37 * k for k in range(40)]

    def pose_bytes(sample, poses, weights):
        roots, nodes = (Trs * models)(), (Trs * total)()
        check(sample() == OK, lib.tutti_last_error())
        check(poses(roots, models, nodes, total) == OK, lib.tutti_last_error())
        w = (ctypes.c_float * morphs)()
        check(weights(body, w, morphs) == OK, lib.tutti_last_error())
        return bytes(roots) + bytes(nodes) + bytes(w)

    expected = [pose_bytes(lambda t=t: lib.tutti_sample(p, t),
                           lambda *a: lib.tutti_poses(p, *a),
                           lambda *a: lib.tutti_model_morph_weights(p, *a)) for t in times]
    contexts = []
    for _ in range(4):
        c = ctypes.c_void_p()
        check(lib.tutti_context_new(p, ctypes.byref(c)) == OK, lib.tutti_last_error())
        contexts.append(c)
    check(lib.tutti_context_poses(contexts[0], None, 0, None, 0) == INVALID_ARGUMENT and
          "tutti_context_sample first" in lib.tutti_last_error().decode(), "poses before sample")
    got = [None] * len(times)
    errors = []

    def work(k):
        try:
            c = contexts[k]
            for i in range(len(times) - 1 - k, -1, -4):
                got[i] = pose_bytes(lambda: lib.tutti_context_sample(c, times[i]),
                                    lambda *a: lib.tutti_context_poses(c, *a),
                                    lambda *a: lib.tutti_context_morph_weights(c, *a))
        except SystemExit as e:  # check() exits: report it from the main thread
            errors.append(str(e))
    threads = [threading.Thread(target=work, args=(k,)) for k in range(4)]
    for t in threads:
        t.start()
    for t in threads:
        t.join()
    check(not errors, errors)
    differing = [round(times[i], 2) for i in range(len(times)) if got[i] != expected[i]]
    check(not differing, f"contexts differ from tutti_sample at {differing}")
    check(lib.tutti_context_sample(None, 1.0) == INVALID_ARGUMENT and
          "NULL" in lib.tutti_last_error().decode(), "a null context")
    check(lib.tutti_context_sample(contexts[0], float("inf")) == INVALID_ARGUMENT, "an infinite time")
    check(lib.tutti_context_new(None, ctypes.byref(ctypes.c_void_p())) == INVALID_ARGUMENT,
          "a context of no performance")
    for c in contexts:
        lib.tutti_context_free(c)
    lib.tutti_context_free(None)
    print(f"capi test: 4 threads, {len(times)} times, each pose as one thread's")


def check_contacts(lib, p, scenes):
    """Contacts as data: who touches what, where and when. Each valve press of Trumpet 1's first
    valve lies inside a span of a fingertip on valve_1; every player's lips touch the mouthpiece;
    a span's point, carried from its part node to the stage by the poses, lies on its body node."""
    total = lib.tutti_contacts(p, -1e9, 1e9, None, 0)
    check(total > 0, f"{total} contacts: {lib.tutti_last_error().decode()}")
    contacts = (Contact * total)()
    check(lib.tutti_contacts(p, -1e9, 1e9, contacts, total) == total, "contacts")
    check(all(contacts[i].from_s <= contacts[i + 1].from_s for i in range(total - 1)),
          "by start time")
    name = lambda m, n: lib.tutti_node_name(p, m, n).decode()
    lips = {c.performer for c in contacts
            if name(c.body_model, c.body_node) == "mouth"
            and name(c.part_model, c.part_node) == "mouthpiece"}
    check(lips == set(range(lib.tutti_performer_count(p))), f"lips of {lips}")
    valve_1 = [c for c in contacts if c.performer == 0 and name(c.part_model, c.part_node) == "valve_1"]
    check(valve_1 and all(name(c.body_model, c.body_node) == "index_tip_r" for c in valve_1),
          "Trumpet 1's index fingertip on valve 1")
    events = (Event * 4096)()
    count = lib.tutti_events(p, -1e9, 1e9, events, 4096)
    valve_down = lib.tutti_event_kind_by_name(b"valve_down")
    downs = [e.t_s for e in events[:count] if e.kind == valve_down and e.performer == 0 and e.value == 1]
    check(downs and all(any(c.from_s <= t <= c.to_s for c in valve_1) for t in downs),
          "every valve-1 press inside a contact span")
    # A window: the spans that overlap it.
    window = lib.tutti_contacts(p, 10.0, 10.5, None, 0)
    check(window == sum(1 for c in contacts if c.to_s >= 10.0 and c.from_s < 10.5) and window > 0,
          f"window: {window}")
    check(lib.tutti_contacts(p, float("nan"), 1.0, None, 0) == -1 and
          "NaN" in lib.tutti_last_error().decode(), "NaN contact window")
    check(lib.tutti_contacts(None, 0.0, 1.0, None, 0) == -1, "a null performance")
    # The point is on its body node in the poses themselves (mid-span, up to 40 spans).
    models = lib.tutti_model_count(p)
    total_nodes = lib.tutti_node_total(p)
    roots, nodes = (Trs * models)(), (Trs * total_nodes)()
    worst = 0.0
    for c in contacts[::max(1, total // 40)]:
        check(lib.tutti_sample(p, 0.5 * (c.from_s + c.to_s)) == OK, "sample")
        check(lib.tutti_poses(p, roots, models, nodes, total_nodes) == OK, "poses")
        at = world_point(lib, p, roots, nodes, c.part_model, c.part_node, c.part_point_m)
        body = world_point(lib, p, roots, nodes, c.body_model, c.body_node, (0.0, 0.0, 0.0))
        worst = max(worst, 1000.0 * math.dist(at, body))
    check(worst < 10.0, f"a contact point {worst:.1f} mm from its body node")
    # contact_fps 0: none recorded.
    options = Options()
    lib.tutti_default_options(ctypes.byref(options))
    check(options.contact_fps > 0, "contacts by default")
    options.contact_fps = 0.0
    handle = ctypes.c_void_p()
    check(lib.tutti_open(os.path.join(scenes, "low_brass.json").encode(), ctypes.byref(options),
                         ctypes.byref(handle)) == OK, lib.tutti_last_error())
    check(lib.tutti_contacts(handle, -1e9, 1e9, None, 0) == 0, "no contacts at contact_fps 0")
    lib.tutti_close(handle)
    options.contact_fps = -1.0
    check(lib.tutti_open(os.path.join(scenes, "low_brass.json").encode(), ctypes.byref(options),
                         ctypes.byref(handle)) == INVALID_ARGUMENT and
          "contact_fps" in lib.tutti_last_error().decode(), "a negative contact_fps")
    print(f"capi test: {total} contact spans, point to body node at most {worst:.2f} mm")


main()
