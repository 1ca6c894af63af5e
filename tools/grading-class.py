#!/usr/bin/env python3
"""A generated class for `glimmer batch --reference`, with its answer key (issue 29).

    tools/grading-class.py FOLDER
        writes FOLDER/class/ (33 submissions of the blur exercise whose solution is
        tests/data/grading/blur/blur.glib) and FOLDER/answer-key.csv (student,
        submission, expected, reason, must_say: the verdict a teacher expects, why,
        and words the row must hold, in its notes or its first diagnostic).

    tools/grading-class.py FOLDER --grade GLIMMER [--load N] [--skip-slow] [-o OUT]
        also grades the class (GLIMMER batch FOLDER/class --reference ... -o OUT,
        OUT = FOLDER/graded by default) with Glimmer's defaults (no --timeout: the
        default time limit, scaled to the solution's own time, is part of what is
        tried), reads OUT/grades.csv, prints a confusion matrix (rows: the key's
        verdict, columns: Glimmer's) and every disagreement with its notes, and
        exits 0 only when every submission is graded as the key says (1 otherwise,
        2 when the grading itself could not run). --load N keeps N busy loops
        running for the whole grading (an artificially loaded machine; otto's
        slow-but-correct blur must still pass). --skip-slow leaves otto out.

The cases: correct work written several ways (the solution as handed out,
separable, while loops and texelFetch, a script with comments and odd spacing,
float counters, the threshold inside the blur, the blur inside the composite,
step(), CRLF line endings, renamed files), subtle mistakes (a threshold on
max(r,g,b), edges that wrap, two off-by-one kernels, weights not normalised, a
picture painted for the default setting, a renamed uniform, a narrower slider
range), broken work (a syntax error, a file named with another case, no script),
messy but honest work (a BOM, a zip whose entries use backslashes, a script three
folders deep, Jürgen, Jörgen and 李雷, a student who handed in a folder and a zip),
hostile work (a zip with a ../ entry, an endless loop, a classmate's shader) and
a slow but correct blur. Standard library only.
"""
import argparse
import csv
import os
import shutil
import subprocess
import sys
import time
import zipfile
from pathlib import Path

from grading_class_shaders import *  # the solution's texts and every case's shaders (tools/grading_class_shaders.py)

VERDICTS = ["pass", "look", "wrong", "error"]


# --------------------------------------------------------------- the class
def solution_files(**changed):
    """The solution's files, some changed or renamed (name -> text; None drops one)."""
    files = {"blur.glib": GLIB, "quad.vert": QUAD, "scene.frag": SCENE, "bright.frag": BRIGHT,
             "blur.frag": BLUR, "add.frag": ADD}
    for name, text in changed.items():
        name = name.replace("__", ".")
        if text is None:
            files.pop(name, None)
        else:
            files[name] = text
    return files


def make_class():
    """[(student as the report names them, path under class/, files or zip entries, kind,
    expected, reason, must_say)]; kind: 'folder' or 'zip'."""
    cases = []

    def add(student, expected, reason, files, path=None, kind="folder", must_say=""):
        cases.append(dict(student=student, path=path or student, files=files, kind=kind,
                          expected=expected, reason=reason, must_say=must_say))

    # Correct work, written several ways.
    add("ada", "pass", "the solution's files as handed out", solution_files())
    add("ben", "pass", "separable: a horizontal then a vertical pass through an RGBA8 target (a level of rounding)",
        solution_files(blur__frag=None, blur1d__frag=BLUR_1D, blur__glib=SEPARABLE_GLIB.replace("BLUR1D", "blur1d.frag")))
    add("chloe", "pass", "while loops and texelFetch with the texel index clamped",
        solution_files(blur__frag=WHILE_TEXELFETCH))
    add("dmitri", "pass", "a script with comments, tabs, odd spacing, a continued Program line, "
        "capitalised file names", {
            "bloom.glib": ODD_SPACING_GLIB, "Quad.vert": QUAD, "Scene.frag": SCENE, "Bright.frag": BRIGHT,
            "Blur.frag": BLUR, "Add.frag": ADD})
    add("elif", "pass", "float loop counters, the weight as a product of two 1-D weights",
        solution_files(blur__frag=FLOAT_COUNTERS))
    add("farah", "pass", "the threshold applied to each tap inside the blur, no bright-pass target",
        solution_files(blur__glib=INLINE_THRESHOLD_GLIB, blur__frag=None, bright__frag=None,
                       glow__frag=INLINE_THRESHOLD_FRAG))
    add("fatima", "pass", "every file saved with Windows line endings (CRLF)",
        {k: v.replace("\n", "\r\n") for k, v in solution_files().items()})
    add("nadia", "pass", "the blur done inside the composite pass (no blur target)",
        solution_files(blur__glib=BLUR_IN_COMPOSITE_GLIB, blur__frag=None, add__frag=None,
                       bloom__frag=BLUR_IN_COMPOSITE_FRAG))
    add("omar", "pass", "step() for the threshold (>= instead of >), textureLod",
        solution_files(bright__frag=STEP_BRIGHT))
    # Messy but honest.
    add("李雷", "pass", "a CJK folder name; separable, comments in Chinese",
        solution_files(blur__frag=None, blur1d__frag=replaced(BLUR_1D, "// One direction", "// 高斯模糊，一维。One direction"),
                       blur__glib=SEPARABLE_GLIB.replace("BLUR1D", "blur1d.frag")))
    add("Jürgen", "pass", "an umlaut in the folder name",
        solution_files(blur__glib=None, **{"jürgens_bloom.glib": GLIB}))
    add("Jörgen", "pass", "another umlaut, the same letters otherwise (must stay a student of its own)",
        solution_files())
    add("hana", "pass", "a zip holding a folder", {f"hana/{k}": v for k, v in solution_files().items()},
        path="hana.zip", kind="zip")
    add("ivan", "pass", "the script and two shaders saved with a UTF-8 BOM",
        solution_files(blur__glib=BOM + GLIB, blur__frag=BOM + BLUR, bright__frag=BOM + BRIGHT))
    add("jonas", "pass", "a zip written by an old Windows tool: entries named with backslashes, a shaders\\ folder",
        {("Hausaufgabe 5\\blur.glib" if k.endswith(".glib") else f"Hausaufgabe 5\\shaders\\{k}"):
         (v.replace("Vertex quad.vert", "Vertex shaders/quad.vert")
          .replace("Fragment ", "Fragment shaders/") if k.endswith(".glib") else v)
         for k, v in solution_files().items()},
        path="jonas.zip", kind="zip")
    add("kofi", "pass", "the script three folders deep (Desktop/cs450/hw5/)",
        {f"Desktop/cs450/hw5/{k}": v for k, v in solution_files().items()})
    add("lena", "pass", "handed in twice: this folder and lena.zip (the row must say so)", solution_files(),
        must_say="handed in more than once")
    add("lena-2", "pass", "handed in twice: lena.zip beside the folder lena (the row must say so)",
        solution_files(), path="lena.zip", kind="zip", must_say="handed in more than once")
    add("otto", "pass", "slow but correct: the bright pass and the normalisation redone for every tap "
        "(about ten times a plain submission's time)",
        solution_files(blur__glib=SLOW_GLIB, blur__frag=None, bright__frag=None, slowblur__frag=SLOW_BLUR))
    add("xavier", "pass", "a narrower slider range, uHalfSize <1 3 4>: right at every setting the grading sets, "
        "the range said in the row", solution_files(blur__glib=replaced(GLIB, "uHalfSize <1 3 6>", "uHalfSize <1 3 4>")),
        must_say="uHalfSize: range <1 4> (the solution's <1 6>)")
    # Subtle mistakes: a person should look.
    add("quinn", "look", "the threshold on max(r,g,b) instead of the luma: the blue and red discs glow",
        solution_files(bright__frag=MAX_BRIGHT))
    add("rosa", "look", "taps not clamped: the edges wrap (the white disc glows on the left edge, the bar on the top)",
        solution_files(blur__frag=WRAP_BLUR))
    add("sami", "look", "off by one: loops i < uHalfSize, the square's last row and column left out (lopsided glow)",
        solution_files(blur__frag=LOPSIDED_BLUR))
    add("tomas", "look", "off by one: half-size uHalfSize - 1 (no blur at all at uHalfSize 1)",
        solution_files(blur__frag=SMALL_BLUR))
    add("wen", "look", "the slider renamed uRadius: the grading cannot move it (the row must name uHalfSize)",
        solution_files(blur__frag=RENAMED_BLUR, blur__glib=GLIB.replace("uHalfSize", "uRadius")),
        must_say="lacks the solution's uniform uHalfSize")
    # Wrong.
    add("uma", "wrong", "weights not normalised: the glow many times too bright",
        solution_files(blur__frag=UNNORMALISED_BLUR))
    add("viktor", "wrong", "painted for the default setting: every slider's value written into the shaders",
        solution_files(bright__frag=PAINTED_BRIGHT, blur__frag=PAINTED_BLUR, add__frag=PAINTED_ADD),
        must_say="is not used by the shaders")
    # Broken.
    add("zoe", "error", "a missing semicolon in blur.frag", solution_files(blur__frag=SYNTAX_BLUR))
    add("pia", "pass", "the script names Blur.frag, the file is blur.frag: opened as Windows would, "
        "with a warning naming both (issue 37)",
        solution_files(blur__glib=replaced(GLIB, "Fragment blur.frag", "Fragment Blur.frag")),
        must_say="'Blur.frag' is 'blur.frag' on disk")
    add("nils", "error", "no script: saved as blur.glib.txt",
        solution_files(blur__glib=None, **{"blur.glib.txt": GLIB}), must_say="blur.glib.txt")
    # Hostile.
    add("mallory", "error", "a zip with an entry ../escape.frag: refused whole",
        dict(solution_files(), **{"../escape.frag": "// out of the folder\n"}), path="mallory.zip", kind="zip",
        must_say="leaves its folder")
    add("spin", "error", "an endless loop (a while whose condition stays true, around heavy work): "
        "stopped by the default time limit",
        solution_files(blur__frag=ENDLESS_BLUR), must_say="timed out")
    add("peter", "error", "the script reads a classmate's shader (../ada/blur.frag): outside the sandbox",
        solution_files(blur__frag=None, blur__glib=replaced(GLIB, "Fragment blur.frag", "Fragment ../ada/blur.frag")),
        must_say="sandbox")
    return cases


def write_class(folder, skip_slow=False):
    folder = Path(folder)
    cls = folder / "class"
    if cls.exists():
        shutil.rmtree(cls)
    cls.mkdir(parents=True)
    cases = [c for c in make_class() if not (skip_slow and c["student"] == "otto")]
    for c in cases:
        if c["kind"] == "zip":
            with zipfile.ZipFile(cls / c["path"], "w", zipfile.ZIP_DEFLATED) as z:
                for name, text in c["files"].items():
                    # ZipInfo keeps a backslash as written (only os.sep is turned into '/').
                    z.writestr(zipfile.ZipInfo(name, date_time=(2026, 11, 20, 12, 0, 0)), text.encode("utf-8"))
        else:
            for name, text in c["files"].items():
                p = cls / c["path"] / name
                p.parent.mkdir(parents=True, exist_ok=True)
                p.write_bytes(text.encode("utf-8"))
    with open(folder / "answer-key.csv", "w", newline="", encoding="utf-8") as f:
        w = csv.writer(f)
        w.writerow(["student", "submission", "expected", "reason", "must_say"])
        for c in sorted(cases, key=lambda c: c["student"]):
            w.writerow([c["student"], c["path"], c["expected"], c["reason"], c["must_say"]])
    return cases


# ---------------------------------------------------------------- grading
def read_key(path):
    with open(path, newline="", encoding="utf-8") as f:
        return {r["student"]: r for r in csv.DictReader(f)}


def read_grades(path):
    with open(path, newline="", encoding="utf-8") as f:
        rows = list(csv.DictReader(f))
    out = {}
    for r in rows:
        # grades.csv defuses formulas with a leading quote; no name here starts with = + - @.
        out[r["student"]] = r
    return out


def confusion(key, grades):
    cols = VERDICTS + ["missing"]
    m = {k: {c: 0 for c in cols} for k in VERDICTS}
    for student, row in key.items():
        got = grades[student]["verdict"] if student in grades else "missing"
        m[row["expected"]][got if got in cols else "missing"] += 1
    return m, cols


def print_matrix(m, cols):
    width = 9
    print("key \\ glimmer".ljust(14) + "".join(c.rjust(width) for c in cols))
    for k in VERDICTS:
        print(k.ljust(14) + "".join(str(m[k][c]).rjust(width) for c in cols))


def grade(args, folder, cases):
    out = Path(args.output) if args.output else folder / "graded"
    if out.exists():
        shutil.rmtree(out)
    cmd = [args.grade, "batch", str(folder / "class"), "--reference", str(SOLUTION / "blur.glib"), "-o", str(out),
           "--size", "128x128", "--jobs", str(args.jobs)]
    if args.backend:
        cmd += ["--backend", args.backend]
    if args.no_sandbox:
        cmd += ["--no-sandbox"]
    loads = []
    try:
        for _ in range(args.load):
            loads.append(subprocess.Popen([sys.executable, "-c", "while True: pass"]))
        if loads:
            time.sleep(1)
        print("grading:", " ".join(cmd), f"(with {args.load} busy loops)" if loads else "", flush=True)
        t0 = time.monotonic()
        r = subprocess.run(cmd, stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True)
        wall = time.monotonic() - t0
        load1 = os.getloadavg()[0]
    finally:
        for p in loads:  # only the loops started here, by their own handles
            p.kill()
            p.wait()
    for line in r.stderr.splitlines():
        if not line.startswith("batch: "):  # the progress line
            print("  " + line)
    print(f"graded in {wall:.1f} s (exit {r.returncode}; load average {load1:.1f} at the end)")
    if r.returncode not in (0, 1) or not (out / "grades.csv").exists():
        print("grading-class.py: the grading did not run to the end", file=sys.stderr)
        return 2
    key = read_key(folder / "answer-key.csv")
    grades = read_grades(out / "grades.csv")
    m, cols = confusion(key, grades)
    print()
    print_matrix(m, cols)
    print()
    bad = 0
    for student in sorted(key):
        k, g = key[student], grades.get(student)
        if g is None:
            print(f"DISAGREE {student}: no row in grades.csv (key: {k['expected']}, {k['reason']})")
            bad += 1
            continue
        said = g["notes"] + " | " + g["first_diagnostic"]
        if g["verdict"] != k["expected"]:
            print(f"DISAGREE {student}: key {k['expected']}, Glimmer {g['verdict']} (score {g['score']}, "
                  f"SSIM {g['ssim']}, PSNR {g['psnr_db']} dB, {g['seconds']} s)\n"
                  f"    key's reason: {k['reason']}\n    notes: {g['notes']}\n    first diagnostic: {g['first_diagnostic']}")
            bad += 1
        elif k["must_say"] and k["must_say"] not in said:
            print(f"DISAGREE {student}: {g['verdict']} as the key says, but the row does not say "
                  f"'{k['must_say']}'\n    notes: {g['notes']}\n    first diagnostic: {g['first_diagnostic']}")
            bad += 1
    for student in sorted(set(grades) - set(key)):
        print(f"DISAGREE {student}: graded ({grades[student]['verdict']}) but not in the answer key")
        bad += 1
    slow = grades.get("otto")
    if slow:
        print(f"otto (slow but correct): {slow['verdict']} in {slow['seconds']} s")
    agree = len(key) - sum(1 for s in key if s not in grades or grades[s]["verdict"] != key[s]["expected"])
    print(f"{agree} of {len(key)} graded as the key says; {bad} disagreement(s)")
    return 0 if bad == 0 else 1


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("folder", help="where class/, answer-key.csv and graded/ go")
    ap.add_argument("--grade", metavar="GLIMMER", help="grade the class with this glimmer binary and compare")
    ap.add_argument("-o", "--output", help="the graded folder (default FOLDER/graded)")
    ap.add_argument("--load", type=int, default=0, metavar="N", help="N busy loops running while grading")
    ap.add_argument("--skip-slow", action="store_true", help="leave out otto, the slow but correct blur")
    ap.add_argument("--jobs", type=int, default=2)
    ap.add_argument("--backend", default="", help="glimmer's --backend (default: its own)")
    ap.add_argument("--no-sandbox", action="store_true", help="grade with --no-sandbox")
    args = ap.parse_args()
    folder = Path(args.folder)
    cases = write_class(folder, args.skip_slow)
    print(f"wrote {folder / 'class'} ({len(cases)} submissions) and {folder / 'answer-key.csv'}")
    if args.grade:
        sys.exit(grade(args, folder, cases))


if __name__ == "__main__":
    main()
