#!/usr/bin/env python3
# SPDX-License-Identifier: MIT
"""The licence is stated everywhere it must be: LICENSE is the MIT licence, every source, build
and script file of ours carries `SPDX-License-Identifier: MIT` in its first three lines, and the
README's licence table names every Debian package the scripts install.

    licence_test.py SOURCE_DIR

Third-party files (tests/data/) and build trees are left out."""
import os
import re
import sys

SLASH = re.compile(r"\.(c|h|cpp|hpp|vert|frag|glsl|comp)$")
HASH = re.compile(r"(\.py|\.sh|CMakeLists\.txt|\.cmake|\.cmake\.in|\.yaml)$")
SKIP_DIRS = {".git", "build", "node_modules", "__pycache__"}


def ours(source):
    for root, dirs, files in os.walk(source):
        rel_root = os.path.relpath(root, source)
        dirs[:] = sorted(d for d in dirs if d not in SKIP_DIRS and not d.startswith("build")
                         and os.path.join(rel_root, d) not in ("tests/data", "./tests/data"))
        for name in sorted(files):
            rel = os.path.normpath(os.path.join(rel_root, name))
            if SLASH.search(name) or HASH.search(name):
                yield rel
            elif rel_root in ("scripts", ".ci") and "." not in name:
                yield rel


def main():
    source = sys.argv[1]
    failures = []
    with open(os.path.join(source, "LICENSE"), encoding="utf-8") as f:
        licence = f.read()
    if not licence.startswith("MIT License") or "Permission is hereby granted" not in licence:
        failures.append("LICENSE is not the MIT licence")
    checked = 0
    for rel in ours(source):
        with open(os.path.join(source, rel), encoding="utf-8", errors="replace") as f:
            head = [f.readline() for _ in range(3)]
        checked += 1
        if not any("SPDX-License-Identifier: MIT" in line for line in head):
            failures.append(f"{rel}: no 'SPDX-License-Identifier: MIT' in its first three lines")
    with open(os.path.join(source, "README.md"), encoding="utf-8") as f:
        readme = f.read()
    table = readme[readme.find("## Licence"):]
    packages = 0
    for listing in ("scripts/packages.txt", "scripts/packages-test.txt"):
        with open(os.path.join(source, listing), encoding="utf-8") as f:
            for line in f:
                package = line.split("#", 1)[0].strip()
                if not package:
                    continue
                packages += 1
                if f"`{package}`" not in table:
                    failures.append(f"README.md's licence table does not name {package} ({listing})")
    for failure in failures:
        print("licence test: FAILED:", failure, file=sys.stderr)
    if failures:
        return 1
    print(f"licence test: passed ({checked} files carry the SPDX line; {packages} packages in the "
          "README's table)")
    return 0


if __name__ == "__main__":
    sys.exit(main())
