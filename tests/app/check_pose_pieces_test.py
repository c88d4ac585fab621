#!/usr/bin/env python3
# SPDX-License-Identifier: MIT
"""Every pose limit on music nobody tuned for: `tutti check-pose --seconds all --json` on every
third-party piece (../shared/testdata's MIDI and MusicXML, and tests/data/pieces/), whole pieces.

    check_pose_pieces_test.py TUTTI TESTDATA_DIR PIECES_DIR BROKEN_LIST KNOWN_OVER [--table FILE]

A piece no performer plays (exit 2, "no part tutti can play") and the files tutti must refuse
(BROKEN_LIST) are skipped. Every other piece must check with exit 0 or 4, and every measure over
its limit must be named in KNOWN_OVER (lines "piece-path | measure-prefix  # why"): a limit
exceeded that is not listed fails the test, and so does a listed one that now holds (the list
only shrinks). With --table, a Markdown table of the figures (worst of each measure over all
pieces) is written to FILE, for the README.
Skips (exit 0, "SKIPPED:") when TESTDATA_DIR is absent.
"""
import json
import os
import subprocess
import sys
from concurrent.futures import ThreadPoolExecutor

TIMEOUT_S = 600


def read_list(path):
    entries = []
    with open(path, encoding="utf-8") as f:
        for line in f:
            line = line.split("#", 1)[0].strip()
            if line:
                entries.append(line)
    return entries


def pieces(testdata, pieces_dir):
    found = []
    for root_name, root in (("", testdata), ("tests/data/pieces/", pieces_dir)):
        for sub in (["midi", "musicxml"] if root_name == "" else [""]):
            top = os.path.join(root, sub)
            for dirpath, _, files in os.walk(top):
                for name in files:
                    if name.lower().endswith((".mid", ".midi", ".xml", ".mxl", ".musicxml")):
                        path = os.path.join(dirpath, name)
                        label = root_name + os.path.relpath(path, root)
                        found.append((label, path))
    return sorted(found)


def check(tutti, path):
    run = subprocess.run([tutti, "check-pose", path, "--seconds", "all", "--json"],
                         capture_output=True, text=True, timeout=TIMEOUT_S)
    return run.returncode, run.stdout, run.stderr


def main():
    args = sys.argv[1:]
    table_path = None
    if "--table" in args:
        i = args.index("--table")
        table_path = args[i + 1]
        del args[i:i + 2]
    tutti, testdata, pieces_dir, broken_list, known_list = args
    if not os.path.isdir(testdata):
        print(f"SKIPPED: {testdata} is absent")
        return 0
    broken = set(read_list(broken_list))
    known = []
    for entry in read_list(known_list):
        piece, _, measure = (part.strip() for part in entry.partition("|"))
        known.append([piece, measure, False])

    todo = [(label, path) for label, path in pieces(testdata, pieces_dir) if label not in broken]
    with ThreadPoolExecutor(max_workers=os.cpu_count() or 1) as pool:
        results = list(pool.map(lambda item: (item, check(tutti, item[1])), todo))

    failures = []
    checked = 0
    worst = {}  # measure name (performer removed) -> [value, piece, at, of, limit text]
    pieces_over = {}  # measure name (performer removed) -> pieces with a performer over the limit
    pieces_with = {}  # measure name (performer removed) -> pieces that have the measure
    for (label, _), (code, out, err) in results:
        if code == 2 and "no part tutti can play" in err:
            continue
        if code not in (0, 4):
            failures.append(f"{label}: exit {code}: {err.strip()[:400]}")
            continue
        checked += 1
        report = json.loads(out)
        for m in report["measures"]:
            name = m["name"]
            performer, _, what = name.partition(": ")
            limit = m.get("limit")
            figure = m["p95"] if limit and limit["of"] == "p95" else (
                max(abs(m["min"]), abs(m["max"])) if limit and limit["of"] == "abs" else m["max"])
            key = what + " (" + m["unit"] + ")"
            if key not in worst or figure > worst[key][0]:
                limit_text = "" if not limit else (
                    {"p95": "p95 ≤ ", "abs": "± ", "max": "≤ "}[limit["of"]] + f"{limit['value']:g}")
                worst[key] = [figure, label, m.get("worst_at_s", 0.0), m.get("worst_of", performer),
                              limit_text, performer]
            pieces_with.setdefault(key, set()).add(label)
            if m["within_limit"]:
                continue
            pieces_over.setdefault(key, set()).add(label)
            listed = [k for k in known if k[0] == label and name.startswith(k[1])]
            for k in listed:
                k[2] = True
            if not listed:
                where = f" at {m.get('worst_at_s', 0.0):.2f} s"
                if m.get("worst_of"):
                    where += f" ({m['worst_of']})"
                failures.append(f"{label}: {name}: {figure:.1f} {m['unit']} over its limit{where}")
    for piece, measure, seen in known:
        if not seen:
            failures.append(f"{piece} | {measure}: listed as over its limit, but it holds now "
                            "(remove it from the known list)")

    rows = sorted(worst.items())
    print(f"{checked} pieces checked, whole; worst figure of each measure:")
    for key, (figure, piece, at, of, limit, performer) in rows:
        print(f"  {key}: {figure:.1f}  [{limit or 'no limit'}]  {piece} at {at:.2f} s ({of or performer})")
    if table_path:
        with open(table_path, "w", encoding="utf-8") as f:
            f.write("| measure | worst over all pieces | limit | pieces over it | where the worst is |\n"
                    "|---|---|---|---|---|\n")
            for key, (figure, piece, at, of, limit, performer) in rows:
                over = f"{len(pieces_over.get(key, ()))} of {len(pieces_with.get(key, ()))}" if limit else "—"
                f.write(f"| {key} | {figure:.1f} | {limit or '—'} | {over} | `{piece}` {at:.2f} s, "
                        f"{performer}{' (' + of + ')' if of and of != performer else ''} |\n")
    for failure in failures:
        print("FAIL: " + failure)
    print(f"{len(failures)} failures; {sum(1 for k in known)} known limits over "
          f"(tests/data/pose_limits_known_over.txt)")
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())
