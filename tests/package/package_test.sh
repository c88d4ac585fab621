#!/usr/bin/env bash
# SPDX-License-Identifier: MIT
# The installed package, used as a game would (docs/embedding.md, "Using the installed package"):
# installs the build into a fresh prefix, checks what was installed, builds the consumer project
# (tests/package/consumer) against it and runs it on a scene from the installed share/ folder
# with the source and build trees out of its reach.
#
#   package_test.sh SOURCE_DIR BUILD_DIR CMAKE CTEST CXX_COMPILER GENERATOR [BUILD_TYPE]
#
# Exit 0: passed; 77: no Vulkan device (ctest: skipped); anything else: failed.
set -euo pipefail

src=$(realpath "$1")
build=$(realpath "$2")
cmake=$3
ctest=$4
cxx=$5
generator=$6
build_type=${7:-}

fail() {
  echo "package test: $*" >&2
  exit 1
}

tmp=$(mktemp -d "${TMPDIR:-/tmp}/tutti-package.XXXXXX")
trap 'rm -rf "$tmp"' EXIT
case "$tmp/" in
  "$src"/* | "$build"/*) fail "the temporary folder $tmp must be outside $src and $build" ;;
esac
prefix=$tmp/prefix

# 1. Install, as a user would.
start=$SECONDS
"$cmake" --install "$build" --prefix "$prefix" >"$tmp/install.log" || {
  cat "$tmp/install.log"
  fail "cmake --install failed"
}
echo "installed into $prefix: $(du -sh "$prefix" | cut -f1), $((SECONDS - start)) s"

# 2. What was installed.
cmakedir=$prefix/lib/cmake/tutti
for file in tuttiConfig.cmake tuttiConfigVersion.cmake tuttiTargets.cmake; do
  [ -f "$cmakedir/$file" ] || fail "missing $cmakedir/$file"
done
# The programs, the C API and its header.
for file in bin/tutti bin/tutti-editor lib/libtutti.so include/tutti/tutti.h; do
  [ -e "$prefix/$file" ] || fail "missing $prefix/$file"
done
"$prefix/bin/tutti" --version >/dev/null || fail "the installed bin/tutti does not run"
# Relocatable: no path of this machine's trees in the CMake files.
if grep -rnF -e "$src" -e "$build" "$cmakedir"; then
  fail "the installed CMake files mention the source or build tree (above)"
fi
# Headers only: no sources, no tests.
if find "$prefix" \( -name '*.cpp' -o -name '*_test.*' -o -name 'CMakeLists.txt' \) | grep .; then
  fail "sources or test files installed (above)"
fi
# Every header's tutti include is another installed header (a header including, say,
# <tutti/cli/...> compiles in the build tree, whose include root holds more than was installed).
include_root=$prefix/include
unresolved=0
while IFS=: read -r header included; do
  if [ ! -f "$include_root/$included" ] && [ ! -f "$(dirname "$header")/$included" ]; then
    echo "${header#"$include_root"/}: #include $included is not installed" >&2
    unresolved=1
  fi
done < <(grep -rHoE --include='*.hpp' --include='*.h' '^#include (<tutti/[^>]*>|"[^"]*")' \
           "$include_root/tutti" | sed -E 's/:#include [<"](.*)[>"]$/:\1/')
[ "$unresolved" -eq 0 ] || fail "headers include files that are not installed (above)"
content=$prefix/share/tutti/content
assets=$prefix/share/tutti/assets
[ -f "$content/scenes/piano.json" ] || fail "missing $content/scenes/piano.json"
[ -f "$content/piano/keyboard.json" ] || fail "missing $content/piano/keyboard.json"
[ -f "$assets/piano.glb" ] || fail "missing $assets/piano.glb"

# 3. The consumer, copied out of the source tree with the example it builds.
mkdir "$tmp/consumer"
cp "$src/tests/package/consumer/CMakeLists.txt" "$src/app/runtime/examples/embed_example.cpp" \
  "$tmp/consumer/"
start=$SECONDS
"$cmake" -S "$tmp/consumer" -B "$tmp/consumer-build" -G "$generator" \
  -DCMAKE_BUILD_TYPE="$build_type" -DCMAKE_CXX_COMPILER="$cxx" \
  -DCMAKE_PREFIX_PATH="$prefix" >"$tmp/configure.log" || {
  cat "$tmp/configure.log"
  fail "configuring the consumer failed"
}
"$cmake" --build "$tmp/consumer-build" || fail "building the consumer failed"
echo "consumer configured and built in $((SECONDS - start)) s"
if grep -rlIF -e "$src" -e "$build" "$tmp/consumer-build"; then
  fail "the consumer's build files refer to the source or build tree (above)"
fi
grep -q "^tutti_DIR:PATH=$cmakedir\$" "$tmp/consumer-build/CMakeCache.txt" ||
  fail "the consumer did not find tutti in $cmakedir"

# 4. Run it on the installed scene, data and models (its ctest sets TUTTI_CONTENT_DIR and
#    TUTTI_ASSET_DIR from tutti_CONTENT_DIR / tutti_ASSET_DIR), with the source and build trees
#    hidden (empty folders mounted over them in a private mount namespace) where unprivileged
#    namespaces are allowed, else with every file access traced (strace) and checked.
run=("$ctest" --test-dir "$tmp/consumer-build" --verbose)
cd "$tmp"
start=$SECONDS
set +e
if unshare --user --map-root-user --mount true 2>/dev/null; then
  echo "running the consumer with $src and $build hidden"
  # The build folder first: it may be inside the source folder.
  unshare --user --map-root-user --mount -- sh -c \
    'mount -t tmpfs tutti-hidden "$1" && mount -t tmpfs tutti-hidden "$2" && shift 2 && exec "$@"' \
    sh "$build" "$src" "${run[@]}" 2>&1 | tee "$tmp/run.log"
  status=${PIPESTATUS[0]}
elif strace -f -qq -e trace=%file -o /dev/null true 2>/dev/null; then
  echo "running the consumer under strace"
  strace -f -qq -e trace=%file -o "$tmp/strace.log" "${run[@]}" 2>&1 | tee "$tmp/run.log"
  status=${PIPESTATUS[0]}
  # ctest itself looks at its own files only; the program must not look in the trees.
  if grep -qF -e "\"$src" -e "\"$build" "$tmp/strace.log"; then
    grep -F -e "\"$src" -e "\"$build" "$tmp/strace.log" | head -20
    fail "the consumer accessed the source or build tree (above)"
  fi
else
  echo "running the consumer (neither unshare nor strace available: the trees stay visible)"
  "${run[@]}" 2>&1 | tee "$tmp/run.log"
  status=${PIPESTATUS[0]}
fi
set -e
echo "consumer ran in $((SECONDS - start)) s"
[ "$status" -eq 0 ] || fail "the consumer's test failed (exit $status)"
if grep -q '\*\*\*Skipped' "$tmp/run.log"; then
  echo "package test: no Vulkan device, the consumer's run was skipped"
  exit 77
fi
grep -q "embed: 5 frames of $content/scenes/piano.json" "$tmp/run.log" ||
  fail "the consumer did not render the installed scene"

# 4b. The installed program finds the installed data by itself (no environment variables), with
#     the trees hidden: it stages the installed quartet and prints its frame.
if unshare --user --map-root-user --mount true 2>/dev/null; then
  unshare --user --map-root-user --mount -- sh -c \
    'mount -t tmpfs tutti-hidden "$1" && mount -t tmpfs tutti-hidden "$2" && shift 2 && exec "$@"' \
    sh "$build" "$src" env -u TUTTI_CONTENT_DIR -u TUTTI_ASSET_DIR "$prefix/bin/tutti" info \
    --schedule "$content/scenes/quartet.json" >"$tmp/schedule.log" 2>&1 ||
    { cat "$tmp/schedule.log"; fail "the installed bin/tutti did not stage the installed quartet"; }
  grep -q "audio_sync" "$tmp/schedule.log" || fail "bin/tutti info --schedule printed no schedule"
  echo "installed bin/tutti staged share/tutti/content/scenes/quartet.json on its own"
fi

# 5. tutti::performance alone, on a machine without Vulkan: the Vulkan headers and loader hidden
#    (an empty folder over /usr/include/vulkan, /dev/null over the loader's file) along with the
#    trees, a host that links only tutti::performance (tests/package/performance_consumer) is
#    configured, built and run: it writes 4 s of Trumpet 1's body as BVH.
mkdir "$tmp/performance-consumer"
cp "$src/tests/package/performance_consumer/CMakeLists.txt" "$src/performance/examples/write_bvh.cpp" \
  "$tmp/performance-consumer/"
loader=$(ls /usr/lib/*/libvulkan.so.1 /usr/lib/libvulkan.so.1 2>/dev/null | head -1 || true)
loader=${loader:+$(readlink -f "$loader")}
cat > "$tmp/no_vulkan.sh" <<SCRIPT
set -e
[ -f /usr/include/vulkan/vulkan.h ] && { echo "Vulkan headers still visible" >&2; exit 1; }
"$cmake" -S "$tmp/performance-consumer" -B "$tmp/performance-build" -G "$generator" \\
  -DCMAKE_BUILD_TYPE="$build_type" -DCMAKE_CXX_COMPILER="$cxx" -DCMAKE_PREFIX_PATH="$prefix"
"$cmake" --build "$tmp/performance-build"
"$ctest" --test-dir "$tmp/performance-build" --output-on-failure
SCRIPT
start=$SECONDS
set +e
if unshare --user --map-root-user --mount true 2>/dev/null; then
  echo "building and running the performance consumer with Vulkan hidden ($loader)"
  unshare --user --map-root-user --mount -- sh -c '
    mount -t tmpfs tutti-hidden "$1" && mount -t tmpfs tutti-hidden "$2" || exit 1
    if [ -d /usr/include/vulkan ]; then mount -t tmpfs no-vulkan /usr/include/vulkan || exit 1; fi
    if [ -n "$3" ]; then mount --bind /dev/null "$3" || exit 1; fi
    exec sh "$4"' sh "$build" "$src" "$loader" "$tmp/no_vulkan.sh" >"$tmp/performance.log" 2>&1
  status=$?
else
  echo "building and running the performance consumer (no namespaces: Vulkan stays visible)"
  sh "$tmp/no_vulkan.sh" >"$tmp/performance.log" 2>&1
  status=$?
fi
set -e
cat "$tmp/performance.log"
[ "$status" -eq 0 ] || fail "the performance consumer failed (exit $status)"
grep -q "tutti: performance TRUE, sound .*, render FALSE" "$tmp/performance.log" ||
  [ -z "$loader" ] || fail "the performance consumer's machine still had Vulkan"
if readelf -d "$tmp/performance-build/write_bvh" | grep -q "libvulkan"; then
  fail "write_bvh needs libvulkan"
fi
bvh=$tmp/performance-build/trumpet.bvh
[ -s "$bvh" ] || fail "no BVH written"
joints=$(grep -c "CHANNELS 6" "$bvh")
frames=$(sed -n 's/^Frames: //p' "$bvh")
[ "$frames" = 120 ] || fail "the BVH has $frames frames, not 120"
values=$(tail -1 "$bvh" | wc -w)
[ "$values" -eq $((joints * 6)) ] || fail "a BVH frame has $values values for $joints joints"
echo "performance consumer: $joints joints x $frames frames of BVH, no Vulkan, $((SECONDS - start)) s"
echo "package test: passed"
