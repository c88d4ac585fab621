#!/usr/bin/env bash
# SPDX-License-Identifier: MIT
# Runs the real `tutti` process on every third-party file and on hostile inputs made here:
# each run must end within the time limit with exit 0 (and a report) or exit 2 (and exactly one
# "error: FILE: ..." line) -- never a crash, a hang or another code.
#   tutti_cli_test.sh TUTTI_BINARY TESTDATA_DIR BROKEN_LIST_FILE
set -u
tutti=$1
testdata=$2
broken_list=$3
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
failures=0
runs=0

fail() { echo "FAIL: $*"; failures=$((failures + 1)); }

# check FILE EXPECT (EXPECT: ok | error | any)
check() {
  local file=$1 expect=$2 code
  runs=$((runs + 1))
  timeout 20 "$tutti" info "$file" --json >"$work/out" 2>"$work/err"
  code=$?
  case $code in
    0)
      grep -q '"notes":' "$work/out" || fail "$file: exit 0 without a report"
      [ -s "$work/err" ] && fail "$file: exit 0 but wrote to stderr: $(head -c 200 "$work/err")"
      [ "$expect" = error ] && fail "$file: expected an error, got exit 0"
      ;;
    2)
      [ "$(wc -l <"$work/err")" -eq 1 ] || fail "$file: error output is not one line: $(cat "$work/err")"
      grep -qF "error: $file: " "$work/err" || fail "$file: error line does not name the file: $(cat "$work/err")"
      [ "$expect" = ok ] && fail "$file: expected success, got: $(cat "$work/err")"
      ;;
    124) fail "$file: hang (killed after 20 s)" ;;
    *) fail "$file: exit code $code: $(tail -c 400 "$work/err")" ;;
  esac
}

if [ -d "$testdata" ]; then
  mapfile -t broken < <(sed -e 's/#.*//' -e 's/[[:space:]]*$//' "$broken_list" | sed '/^$/d')
  is_broken() { local b; for b in "${broken[@]}"; do [ "$b" = "$1" ] && return 0; done; return 1; }
  while IFS= read -r -d '' file; do
    name=${file#"$testdata"/}
    if is_broken "$name"; then check "$file" error; else check "$file" ok; fi
  done < <(find "$testdata/midi" "$testdata/musicxml" -type f \
             \( -name '*.mid' -o -name '*.xml' -o -name '*.mxl' -o -name '*.musicxml' \) -print0 | sort -z)

  # Every prefix length of a real file, sampled: truncation anywhere is an error or a shorter
  # score, never a crash.
  for source in "$testdata/midi/tonejs/bach_846.mid" \
                "$testdata/musicxml/lilypond-test-suite/90a-Compressed-MusicXML.mxl" \
                "$testdata/musicxml/music21/bwv69.6.xml"; do
    size=$(stat -c %s "$source")
    ext=${source##*.}
    for cut in 1 3 13 14 22 23 30 $((size / 7)) $((size / 3)) $((size / 2)) $((size - 2)) $((size - 1)); do
      [ "$cut" -lt "$size" ] || continue
      head -c "$cut" "$source" >"$work/cut-$cut.$ext"
      check "$work/cut-$cut.$ext" any
    done
  done
else
  echo "SKIPPED: $testdata not found; third-party files not checked"
fi

# Hand-made hostile inputs.
printf 'MThd\0\0\0\6\0\1\0\1\1\340MTrk\377\377\377\360\0\377\57\0' >"$work/lying-length.mid"
check "$work/lying-length.mid" error
printf 'MThd\377\377\377\377' >"$work/lying-header.mid"
check "$work/lying-header.mid" error
: >"$work/empty.mid"
check "$work/empty.mid" error
printf '<?xml version="1.0"?><score-partwise><part-list>' >"$work/truncated.musicxml"
check "$work/truncated.musicxml" error
printf 'PK\3\4garbage' >"$work/not-a-zip.mxl"
check "$work/not-a-zip.mxl" error
check "$work/does-not-exist.mid" error
mkdir "$work/folder.mid"
check "$work/folder.mid" error

echo "tutti_cli_test: $runs runs, $failures failures"
[ "$failures" -eq 0 ]
