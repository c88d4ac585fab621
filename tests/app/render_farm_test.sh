#!/usr/bin/env bash
# SPDX-License-Identifier: MIT
# A render split with an existing job runner (GNU parallel, as docs/render_farm.md shows), joined
# by `tutti concat`, equals a single render frame for frame and sample for sample; slices that do
# not fit together are one-line errors.
#   render_farm_test.sh TUTTI_BINARY SOURCE_DIR
set -u
tutti=$1
source_dir=$2
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
failures=0
fail() { echo "FAIL: $*"; failures=$((failures + 1)); }
if ! command -v parallel >/dev/null; then
  echo "SKIPPED: GNU parallel is not installed (scripts/setup installs it)"
  exit 0
fi
cd "$work" || exit 1
# The piano demo, small and short: 3 s to 5 s of the music at 160x90, 60 frames.
sed -e "s|\"../music/|\"$source_dir/content/music/|" \
    -e 's|"width": 1280, "height": 720|"width": 160, "height": 90|' \
    -e 's|"start_s": 0, "end_s": null|"start_s": 3.0, "end_s": 5.0|' \
    "$source_dir/content/scenes/piano.json" >small.json
grep -q '"width": 160' small.json && grep -q '"start_s": 3.0' small.json || fail "could not shrink the scene"

# Three slices in three processes at once, then one render of the whole.
parallel -j3 --halt now,fail=1 \
  "$tutti" render small.json --frames {1}:{2} --no-audio --lossless --no-progress -o slice_{#}.mp4 \
  ::: 0 20 40 :::+ 20 40 60 >parallel.log 2>&1 || fail "parallel render: $(cat parallel.log)"
"$tutti" render small.json --lossless --no-progress -o single.mp4 >/dev/null 2>render.err ||
  fail "single render: $(cat render.err)"
# Any order on the command line.
"$tutti" concat small.json slice_3.mp4 slice_1.mp4 slice_2.mp4 -o joined.mp4 >concat.out 2>concat.err ||
  fail "concat: $(cat concat.err)"
grep -q "3 slices, frames 0:60" concat.out || fail "concat report: $(cat concat.out)"
for f in single joined; do
  ffmpeg -nostdin -loglevel error -i $f.mp4 -f rawvideo -pix_fmt rgb24 $f.rgb || fail "decode $f video"
  ffmpeg -nostdin -loglevel error -i $f.mp4 -vn -f s16le $f.pcm || fail "decode $f audio"
done
[ "$(stat -c %s single.rgb)" -eq $((160 * 90 * 3 * 60)) ] || fail "single render is not 60 frames"
cmp -s single.rgb joined.rgb || fail "joined frames differ from the single render"
[ -s single.pcm ] || fail "no audio in the single render"
cmp -s single.pcm joined.pcm || fail "joined audio differs from the single render"

# Slices that do not fit together.
expect_error() {  # NEEDLE ARGS...
  local needle=$1 code
  shift
  "$tutti" concat small.json "$@" >/dev/null 2>err
  code=$?
  [ $code -eq 2 ] || fail "concat $*: exit $code, expected 2"
  [ "$(wc -l <err)" -eq 1 ] || fail "concat $*: not one line: $(cat err)"
  grep -qF -- "$needle" err || fail "concat $*: '$needle' not in: $(cat err)"
}
expect_error "slice_3.mp4: starts at frame 40 but slice_1.mp4 ends at frame 20 (frames missing)" \
  slice_1.mp4 slice_3.mp4 -o gap.mp4
"$tutti" render small.json --frames 10:30 --no-audio --lossless --no-progress -o overlap.mp4 >/dev/null 2>&1
expect_error "(frames overlap)" slice_1.mp4 overlap.mp4 -o overlap_joined.mp4
"$tutti" render small.json --frames 20:40 --no-audio --no-progress -o lossy.mp4 >/dev/null 2>&1
expect_error "lossy.mp4: rendered with other settings than" slice_1.mp4 lossy.mp4 -o mixed.mp4
ffmpeg -nostdin -loglevel error -f lavfi -i color=c=black:s=32x32:d=1 -c:v libx264 other.mp4
expect_error "other.mp4: not a slice made by tutti render" other.mp4 -o x.mp4
expect_error "missing.mp4: no such file" missing.mp4 -o x.mp4
expect_error "x.mkv: the output is an .mp4 file" slice_1.mp4 -o x.mkv
[ -e gap.mp4 ] && fail "a failed concat left gap.mp4"
echo "render_farm_test: $failures failures"
[ $failures -eq 0 ]
