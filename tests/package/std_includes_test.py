#!/usr/bin/env python3
# SPDX-License-Identifier: MIT
"""Every public header includes the standard and GLM headers it uses, itself or through the tutti
headers it includes: what the header check (tests/package, each header compiled alone) no longer
sees, since it compiles them on a precompiled header of these (header_check_precompiled.hpp).

    std_includes_test.py INCLUDE_ROOT HEADER_LIST PRECOMPILED_HEADER

INCLUDE_ROOT holds tutti/<folder>/... (the build tree's include/); HEADER_LIST is a file with one
public header per line, as included ("scene/scene.hpp"). Prints each header that uses a name
without its header, and each header of PRECOMPILED_HEADER that no name here checks, and exits 1;
0 when there are none."""
import os
import re
import sys

ANY_STANDARD_HEADER = "any standard header"
# A name of the standard library (or GLM) and the headers any one of which declares it. What the
# precompiled header holds must be here, or the header check stops seeing it. Lenient where the
# standard puts a name in several headers.
NAMES = [
    (r"std::vector\b", ["vector"]),
    (r"std::(?:basic_)?string\b(?!_view)", ["string"]),
    (r"std::(?:basic_)?string_view\b", ["string_view", "string"]),
    (r"std::span\b|std::dynamic_extent\b", ["span"]),
    (r"std::(?:optional|nullopt|make_optional)\b", ["optional"]),
    (r"std::filesystem::", ["filesystem"]),
    (r"std::array\b", ["array"]),
    (r"std::(?:unique_ptr|shared_ptr|weak_ptr|make_unique|make_shared|enable_shared_from_this)\b",
     ["memory"]),
    (r"std::(?:function|reference_wrapper|hash)\b", ["functional"]),
    (r"std::(?:multi)?map\b", ["map"]),
    (r"std::unordered_map\b", ["unordered_map"]),
    (r"std::(?:variant|monostate|visit|holds_alternative|get_if)\b", ["variant"]),
    (r"std::(?:any|any_cast)\b", ["any"]),
    (r"std::deque\b", ["deque"]),
    (r"std::(?:tuple|tie|make_tuple|apply)\b", ["tuple"]),
    (r"std::numeric_limits\b", ["limits"]),
    (r"std::(?:sort|stable_sort|find|find_if|lower_bound|upper_bound|clamp|min_element|"
     r"max_element|any_of|all_of|none_of|count_if|fill|copy|equal|reverse|transform)\b",
     ["algorithm"]),
    (r"std::(?:sqrt|pow|sin|cos|atan2|floor|ceil|round|lround|exp|log|log2|isfinite|isnan|"
     r"fabs|fmod|hypot)\b", ["cmath"]),
    (r"std::(?:u?int(?:8|16|32|64)_t)\b", ["cstdint"]),
    # Every standard header that uses a size declares std::size_t in practice (the compile-alone
    # check accepted it from any of them too).
    (r"std::(?:size_t|ptrdiff_t)\b", ["cstddef", ANY_STANDARD_HEADER]),
    (r"std::byte\b", ["cstddef"]),
    (r"std::(?:pair|make_pair|move|forward|exchange|swap|in_place|index_sequence)\b",
     ["utility"]),
    (r"std::(?:is_\w+|enable_if|conditional|decay|remove_\w+|integral_constant|"
     r"invoke_result|underlying_type)(?:_t|_v)?\b", ["type_traits"]),
    (r"std::(?:strong|weak|partial)_ordering\b", ["compare"]),
    (r"std::initializer_list\b", ["initializer_list"]),
    (r"std::atomic\b", ["atomic"]),
    (r"\bglm::(?:[iu]?vec[234]|mat[234]|dvec[234]|dmat[234]|radians|degrees|dot|cross|"
     r"normalize|length|distance|mix|clamp|inverse|transpose)\b", ["glm/glm.hpp"]),
    (r"\bglm::(?:quat|dquat|angleAxis|mat4_cast|quat_cast|slerp|conjugate|eulerAngles)\b",
     ["glm/gtc/quaternion.hpp", "glm/ext/quaternion_float.hpp"]),
]
NAME_PATTERNS = [(re.compile(p), headers) for p, headers in NAMES]
INCLUDE = re.compile(r'^\s*#\s*include\s*[<"]([^>"]+)[>"]', re.M)
# GLM's own headers include each other: any glm/ header brings glm.hpp's types.
GLM_TYPES_FROM_ANY = "glm/glm.hpp"
# Standard headers that include others in every implementation (the standard says so).
IMPLIED = {"string": {"string_view"}, "map": {"utility", "initializer_list"},
           "unordered_map": {"utility", "initializer_list"}, "vector": {"initializer_list"},
           "utility": {"initializer_list", "compare"}, "array": {"compare", "initializer_list"},
           "tuple": {"compare"}, "memory": {"compare"}, "optional": {"compare"},
           "variant": {"compare"}, "string_view": {"compare"}, "filesystem": {"compare"},
           "deque": {"compare", "initializer_list"}, "atomic": set(), "any": set()}


def strip_comments_and_strings(text):
    text = re.sub(r"/\*.*?\*/", " ", text, flags=re.S)
    text = re.sub(r"//[^\n]*", " ", text)
    return re.sub(r'"(?:\\.|[^"\\\n])*"', '""', text)


def reachable_includes(header, root, cache):
    """Every non-tutti include of `header` and of the tutti headers it includes, transitively."""
    if header in cache:
        return cache[header]
    cache[header] = set()  # a cycle ends here
    found = set()
    with open(os.path.join(root, "tutti", header), encoding="utf-8") as f:
        text = f.read()
    for included in INCLUDE.findall(strip_comments_and_strings_keep_includes(text)):
        if included.startswith("tutti/"):
            found |= reachable_includes(included[len("tutti/"):], root, cache)
        else:
            found.add(included)
            found |= IMPLIED.get(included, set())
            if "/" not in included and "." not in included:
                found.add(ANY_STANDARD_HEADER)
            if included.startswith("glm/"):
                found.add(GLM_TYPES_FROM_ANY)
    cache[header] = found
    return found


def strip_comments_and_strings_keep_includes(text):
    text = re.sub(r"/\*.*?\*/", " ", text, flags=re.S)
    return re.sub(r"//[^\n]*", " ", text)


def main():
    if len(sys.argv) != 4:
        print(__doc__, file=sys.stderr)
        return 2
    root, header_list, precompiled = sys.argv[1], sys.argv[2], sys.argv[3]
    checked_headers = {w for _, wanted in NAMES for w in wanted}
    with open(precompiled, encoding="utf-8") as f:
        unchecked = [h for h in INCLUDE.findall(strip_comments_and_strings_keep_includes(f.read()))
                     if h not in checked_headers]
    with open(header_list, encoding="utf-8") as f:
        headers = [line.strip() for line in f if line.strip()]
    cache = {}
    missing = []
    for header in headers:
        with open(os.path.join(root, "tutti", header), encoding="utf-8") as f:
            code = strip_comments_and_strings(f.read())
        have = reachable_includes(header, root, cache)
        for pattern, wanted in NAME_PATTERNS:
            match = pattern.search(code)
            if match and not any(w in have for w in wanted):
                missing.append(f"{header}: uses {match.group(0)} but includes no "
                               + " or ".join(w if w == ANY_STANDARD_HEADER else f"<{w}>"
                                             for w in wanted)
                               + " (itself or through the tutti headers it includes)")
    missing += [f"{precompiled}: <{h}> is precompiled for the header check but no name of it is "
                "checked here" for h in unchecked]
    for line in missing:
        print(line)
    print(f"{len(headers)} public headers checked, {len(missing)} missing includes")
    return 1 if missing else 0


if __name__ == "__main__":
    sys.exit(main())
