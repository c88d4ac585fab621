#!/usr/bin/env python3
"""Writes the tutti fingering corpus (PIG text files) from standard piano pedagogy.

Encoded by the tutti project from common-knowledge textbook fingerings; CC0.
Python 3, standard library only. Run from anywhere: python3 make_corpus.py
Output: train/*.txt and heldout/*.txt next to this script (existing .txt files are replaced).
"""
import os

HERE = os.path.dirname(os.path.abspath(__file__))
NAMES = ["C", "C#", "D", "D#", "E", "F", "F#", "G", "G#", "A", "A#", "B"]
STEP = 0.25  # seconds per note, legato

# Held out entirely: every scale and arpeggio on these tonics, and every exercise pattern.
HELDOUT_TONICS = {"D", "F#", "Ab", "Bb"}

MAJOR = [0, 2, 4, 5, 7, 9, 11]
HARMONIC_MINOR = [0, 2, 3, 5, 7, 8, 11]
TONIC_PC = {"C": 0, "C#": 1, "Db": 1, "D": 2, "Eb": 3, "D#": 3, "E": 4, "F": 5, "F#": 6,
            "G": 7, "Ab": 8, "G#": 8, "A": 9, "Bb": 10, "B": 11}

# Two octaves ascending (15 notes), right hand then left hand. Descending = the same fingers
# in reverse (the standard fingering is the same note for note in both directions).
MAJOR_SCALES = {
    "C":  ("123123412312345", "543213214321321"),
    "G":  ("123123412312345", "543213214321321"),
    "D":  ("123123412312345", "543213214321321"),
    "A":  ("123123412312345", "543213214321321"),
    "E":  ("123123412312345", "543213214321321"),
    "B":  ("123123412312345", "432143213214321"),
    "F#": ("234123123412312", "432132143213214"),
    "Db": ("231234123123412", "321432132143213"),
    "Ab": ("341231234123123", "321432132143213"),
    "Eb": ("312341231234123", "321432132143213"),
    "Bb": ("412312341231234", "321432132143213"),
    "F":  ("123412312341234", "543213214321321"),
}
HARMONIC_MINOR_SCALES = {
    "A":  ("123123412312345", "543213214321321"),
    "E":  ("123123412312345", "543213214321321"),
    "B":  ("123123412312345", "432143213214321"),
    "F#": ("341231234123123", "432132143213214"),
    "C#": ("341231234123123", "321432132143213"),
    "G#": ("341231234123123", "321432132143213"),
    "Eb": ("312341231234123", "214321321432132"),
    "Bb": ("412312341231234", "213214321321432"),
    "F":  ("123412312341234", "543213214321321"),
    "C":  ("123123412312345", "543213214321321"),
    "G":  ("123123412312345", "543213214321321"),
    "D":  ("123123412312345", "543213214321321"),
}
# Root-position triad arpeggios, two octaves (7 notes up, then back down), on white-key roots
# (the fingerings every method agrees on). Left hand: 5-4-2-1 when the third is a white key
# after a white root, 5-3-2-1 when it is a black key.
ARPEGGIOS_MAJOR = ["C", "D", "E", "F", "G", "A"]
ARPEGGIOS_MINOR = ["C", "D", "E", "G", "A"]


def arpeggio_fingers(root_pc, third_pc):
    rh = "1231235"
    black_third = third_pc % 12 in (1, 3, 6, 8, 10)
    lh = "5321321" if black_third else "5421421"
    return rh, lh


class Piece:
    def __init__(self):
        self.notes = []  # (onset, offset, key, channel, finger)

    def line(self, keys, fingers, channel, start=0.0, step=STEP):
        assert len(keys) == len(fingers), (keys, fingers)
        t = start
        for k, f in zip(keys, fingers):
            self.notes.append((t, t + step, k, channel, int(f)))
            t += step
        return t

    def chord(self, keys, fingers, channel, start, length):
        assert len(keys) == len(fingers)
        for k, f in zip(keys, fingers):
            self.notes.append((start, start + length, k, channel, int(f)))

    def write(self, path, title):
        self.notes.sort(key=lambda n: (n[0], n[3], n[2]))
        with open(path, "w", encoding="utf-8", newline="\n") as out:
            out.write("//Version: PigletFormat 1.0 tutti fingering corpus (CC0): %s\n" % title)
            for i, (on, off, key, ch, f) in enumerate(self.notes):
                name = NAMES[key % 12] + str(key // 12 - 1)
                finger = f if ch == 0 else -f
                out.write("%d\t%.4f\t%.4f\t%s\t64\t64\t%d\t%d\n" % (i, on, off, name, ch, finger))


def up_down(keys, fingers):
    return keys + keys[-2::-1], fingers + fingers[-2::-1]


def scale_keys(tonic_pc, steps, start_octave_key):
    base = start_octave_key + tonic_pc
    keys = [base + 12 * o + s for o in range(2) for s in steps] + [base + 24]
    return keys


def both_hands(piece, rh_keys, rh_f, lh_keys, lh_f):
    k, f = up_down(rh_keys, list(rh_f))
    piece.line(k, f, 0)
    k, f = up_down(lh_keys, list(lh_f))
    piece.line(k, f, 1)


def write_scales(outputs):
    for kind, table, steps in (("major", MAJOR_SCALES, MAJOR),
                               ("minor", HARMONIC_MINOR_SCALES, HARMONIC_MINOR)):
        for tonic, (rh, lh) in table.items():
            pc = TONIC_PC[tonic]
            p = Piece()
            both_hands(p, scale_keys(pc, steps, 60), rh, scale_keys(pc, steps, 36), lh)
            split = "heldout" if tonic in HELDOUT_TONICS or TONIC_PC[tonic] in {
                TONIC_PC[t] for t in HELDOUT_TONICS} else "train"
            name = "scale_%s_%s.txt" % (kind, tonic.replace("#", "sharp").replace("b", "flat")
                                        if len(tonic) > 1 else tonic)
            outputs.append((split, name, p, "%s %s scale, 2 octaves up and down" % (tonic, kind)))


def write_arpeggios(outputs):
    for kind, roots, third in (("major", ARPEGGIOS_MAJOR, 4), ("minor", ARPEGGIOS_MINOR, 3)):
        for root in roots:
            pc = TONIC_PC[root]
            rh, lh = arpeggio_fingers(pc, pc + third)
            chord = [0, third, 7]
            rk = [60 + pc + 12 * o + s for o in range(2) for s in chord] + [60 + pc + 24]
            lk = [36 + pc + 12 * o + s for o in range(2) for s in chord] + [36 + pc + 24]
            p = Piece()
            both_hands(p, rk, rh, lk, lh)
            split = "heldout" if pc in {TONIC_PC[t] for t in HELDOUT_TONICS} else "train"
            outputs.append((split, "arpeggio_%s_%s.txt" % (kind, root), p,
                            "%s %s arpeggio, 2 octaves up and down" % (root, kind)))


def write_exercises(outputs):
    # Five-finger patterns (major, up and down) in C, G, F, D: RH 1-5-1, LH 5-1-5.
    for root in ("C", "G", "F", "D"):
        pc = TONIC_PC[root]
        steps = [0, 2, 4, 5, 7]
        p = Piece()
        both_hands(p, [60 + pc + s for s in steps], "12345", [48 + pc + s for s in steps], "54321")
        outputs.append(("heldout", "five_finger_%s.txt" % root, p, "five-finger pattern in " + root))
    # Hanon No. 1 in C: C E F G A G F E, then up a step, 14 groups up; RH 1-2-3-4-5-4-3-2,
    # LH (an octave lower, same notes) 5-4-3-2-1-2-3-4.
    white = [0, 2, 4, 5, 7, 9, 11]

    def white_key(index, base):
        return base + 12 * (index // 7) + white[index % 7]

    p = Piece()
    rk, lk, rf, lf = [], [], "", ""
    for g in range(14):
        pattern = [0, 2, 3, 4, 5, 4, 3, 2]
        rk += [white_key(g + i, 60) for i in pattern]
        lk += [white_key(g + i, 48) for i in pattern]
        rf += "12345432"
        lf += "54321234"
    p.line(rk, rf, 0)
    p.line(lk, lf, 1)
    outputs.append(("heldout", "hanon_1_C.txt", p, "Hanon No. 1 in C, ascending"))
    # Broken chords in C: I, IV, V, I in close position, RH 1-3-5-3, LH 5-3-1-3.
    p = Piece()
    rk, lk, rf, lf = [], [], "", ""
    for r_ch, r_f, l_ch, l_f in (([60, 64, 67], "135", [48, 52, 55], "531"),
                                 ([60, 65, 69], "135", [41, 45, 48], "531"),
                                 ([59, 62, 67], "125", [43, 47, 50], "531"),
                                 ([60, 64, 67], "135", [48, 52, 55], "531")):
        for _ in range(2):
            rk += [r_ch[0], r_ch[1], r_ch[2], r_ch[1]]
            rf += r_f[0] + r_f[1] + r_f[2] + r_f[1]
            lk += [l_ch[0], l_ch[1], l_ch[2], l_ch[1]]
            lf += l_f[0] + l_f[1] + l_f[2] + l_f[1]
    p.line(rk, rf, 0)
    p.line(lk, lf, 1)
    outputs.append(("heldout", "broken_chords_C.txt", p, "broken chords I-IV-V-I in C"))
    # Block chords I - IV6/4 - V6 - I in C (RH 1-3-5 / 1-3-5 / 1-2-5 / 1-3-5), LH root position
    # 5-3-1; and the same in G.
    for name, t in (("C", 0), ("G", 7)):
        p = Piece()
        progression = (([60, 64, 67], "135", [48, 52, 55], "531"),
                       ([60, 65, 69], "135", [41, 45, 48], "531"),
                       ([59, 62, 67], "125", [43, 47, 50], "531"),
                       ([60, 64, 67], "135", [48, 52, 55], "531"))
        for i, (r_ch, r_f, l_ch, l_f) in enumerate(progression):
            p.chord([k + t for k in r_ch], r_f, 0, i * 1.0, 0.9)
            p.chord([k + t - (12 if t else 0) for k in l_ch], l_f, 1, i * 1.0, 0.9)
        outputs.append(("heldout", "block_chords_%s.txt" % name, p,
                        "block chords I-IV-V-I in " + name))


def main():
    outputs = []
    write_scales(outputs)
    write_arpeggios(outputs)
    write_exercises(outputs)
    for split in ("train", "heldout"):
        d = os.path.join(HERE, split)
        os.makedirs(d, exist_ok=True)
        for f in os.listdir(d):
            if f.endswith(".txt"):
                os.remove(os.path.join(d, f))
    counts = {}
    for split, name, piece, title in outputs:
        piece.write(os.path.join(HERE, split, name), title)
        counts[split] = counts.get(split, 0) + len(piece.notes)
    print("wrote", len(outputs), "files:", counts)


if __name__ == "__main__":
    main()
