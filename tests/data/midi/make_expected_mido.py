#!/usr/bin/python3
"""Independent expectations for the MIDI reader tests, computed with the python `mido` library.

For every .mid file under <testdata>/midi (all sub-folders) this records what mido makes of it:
  ok      -- mido parses it (clip=False, default strictness)
  notes   -- note_on messages with velocity > 0 over all tracks (velocity 0 is a note-off)
  length  -- MidiFile.length in seconds; null for type 2 files (mido refuses) and unparsable
             ones (length_note says when a mido bug had to be worked around)
  error   -- mido's complaint when ok is false (for humans; the C++ test ignores it)

Usage (the JSON goes to stdout; the C++ test reads the committed copy and never runs python):
  /usr/bin/python3 tests/data/midi/make_expected_mido.py ../shared/testdata > \
      tests/data/midi/mido_expected.json
Generated with Debian's python3-mido 1.2.10.
"""

import json
import pathlib
import sys

import mido


def describe(path: pathlib.Path) -> dict:
    entry = {"ok": False, "notes": None, "length": None, "error": None}
    try:
        midi = mido.MidiFile(str(path), clip=False)
    except Exception as error:  # mido raises IOError, EOFError, ValueError, KeyError, ...
        entry["error"] = f"{type(error).__name__}: {error}"
        return entry
    entry["ok"] = True
    entry["notes"] = sum(1 for track in midi.tracks for msg in track
                         if msg.type == "note_on" and msg.velocity > 0)
    if midi.type != 2:
        try:
            entry["length"] = float(midi.length)
        except TypeError as error:
            # mido 1.2.10 cannot copy() an UnknownMetaMessage (a meta type it has no name for),
            # which MidiFile.length does for every message. Such a message carries no timing
            # beyond its delta time, so swap it for a plain text meta with the same delta and
            # let mido compute the length again.
            for track in midi.tracks:
                track[:] = [mido.MetaMessage("text", text="", time=msg.time)
                            if isinstance(msg, mido.midifiles.meta.UnknownMetaMessage) else msg
                            for msg in track]
            entry["length"] = float(midi.length)
            entry["length_note"] = f"unknown meta messages replaced ({error})"
    return entry


def main() -> None:
    root = pathlib.Path(sys.argv[1] if len(sys.argv) > 1 else "../shared/testdata")
    files = sorted(p for p in (root / "midi").rglob("*") if p.suffix.lower() in (".mid", ".midi"))
    result = {
        "generator": f"tests/data/midi/make_expected_mido.py with mido {mido.__version__}",
        "files": {p.relative_to(root).as_posix(): describe(p) for p in files},
    }
    json.dump(result, sys.stdout, indent=1, sort_keys=True)
    sys.stdout.write("\n")


if __name__ == "__main__":
    main()
