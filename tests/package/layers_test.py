#!/usr/bin/env python3
# SPDX-License-Identifier: MIT
"""The tree's layers (docs/architecture.md), checked on every include of ours: a file may include
the libraries of its own layer and of the layers below it, never one above; an instrument family
(plugins/) includes no other family. Libraries are the folders with a CMakeLists.txt under each
layer's folder, included as <tutti/<folder>/...>.

    layers_test.py SOURCE_DIR

Prints each file that breaks a rule, with the include and both layers, and exits 1; 0 when there
are none."""
import os
import re
import sys

# Lowest first. content/generator makes the assets from the systems' dimensions.
LAYERS = [("engine", 0), ("components", 1), ("systems", 2), ("content", 2), ("scene", 3),
          ("stage", 4), ("plugins", 5), ("performance", 6), ("app", 7), ("editor", 7)]
LAYER_NAMES = ["engine", "components", "systems and content", "scene", "stage", "plugins",
               "performance", "app and editor"]
INCLUDE = re.compile(r'^\s*#\s*include\s*<tutti/([A-Za-z0-9_]+)/')


def libraries(root):
    """{include folder: (layer, folder path)} of every library folder of ours."""
    found = {}
    for top, layer in LAYERS:
        top_dir = os.path.join(root, top)
        if not os.path.isdir(top_dir):
            continue
        if top in ("components", "scene", "stage", "performance", "editor"):
            found[top] = (layer, top)
        for sub in sorted(os.listdir(top_dir)):
            if os.path.isfile(os.path.join(top_dir, sub, "CMakeLists.txt")):
                found.setdefault(sub, (layer, top + "/" + sub))
    return found


def library_of(path, found):
    """The library whose folder holds `path` (the deepest), or None."""
    best = None
    for name, (layer, folder) in found.items():
        if path == folder or path.startswith(folder + "/"):
            if best is None or len(folder) > len(found[best][1]):
                best = name
    return best


def main():
    if len(sys.argv) != 2:
        print(__doc__, file=sys.stderr)
        return 2
    root = sys.argv[1]
    found = libraries(root)
    broken = []
    checked = 0
    for top, _ in LAYERS:
        for dirpath, _, files in os.walk(os.path.join(root, top)):
            for name in sorted(files):
                if not name.endswith((".hpp", ".cpp", ".h", ".inl")):
                    continue
                path = os.path.relpath(os.path.join(dirpath, name), root)
                own = library_of(path, found)
                if own is None:
                    continue
                own_layer, own_folder = found[own]
                checked += 1
                with open(os.path.join(root, path), encoding="utf-8", errors="replace") as f:
                    for number, line in enumerate(f, 1):
                        match = INCLUDE.match(line)
                        if not match or match.group(1) not in found:
                            continue
                        other = match.group(1)
                        other_layer, other_folder = found[other]
                        if other_layer > own_layer:
                            broken.append(f"{path}:{number}: includes <tutti/{other}/...> "
                                          f"({other_folder}, {LAYER_NAMES[other_layer]}) from "
                                          f"{LAYER_NAMES[own_layer]}, a layer below it")
                        elif own_layer == 5 and other_layer == 5 and other != own:
                            broken.append(f"{path}:{number}: the family {own_folder} includes "
                                          f"another family's <tutti/{other}/...>")
    for line in broken:
        print(line)
    print(f"layers: {checked} files of {len(found)} libraries checked, "
          f"{len(broken)} includes across the layers")
    return 1 if broken else 0


if __name__ == "__main__":
    sys.exit(main())
