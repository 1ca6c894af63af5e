#!/usr/bin/env bash
# Times two glimmer binaries (two builds of the same source, e.g. with and
# without a compiler flag) on the same work, their runs interleaved so that
# a busy machine slows both alike; prints each one's median and B/A.
# Work: the seed bloom rendered at 1024x1024, `check` of it, and the
# generated class graded at 128x128 with one worker (the CPU's part of
# grading: PNG decode, SSIM, the report). The grades of A and B must agree.
# Usage: tools/bench-two-builds.sh GLIMMER_A GLIMMER_B [RUNS] (default 5)
# Needs the generated class: ctest --test-dir build -R grading.class (or
# tools/grading-class.py build/tests/grading-class).
set -euo pipefail
cd "$(dirname "$0")/.."
a="$1" b="$2" runs="${3:-5}"
class=build/tests/grading-class/class
[ -d "$class" ] || { echo "bench-two-builds: $class is missing (see the usage line)" >&2; exit 2; }
out="$(mktemp -d)"
trap 'rm -rf "$out"' EXIT
secs() { local s; s=$(date +%s.%N); "$@" >/dev/null 2>&1 || true; echo "$(date +%s.%N) - $s" | bc; }
for ((i = 0; i < runs; i++)); do
  for which in A B; do
    bin=$a; [ "$which" = B ] && bin=$b
    rm -rf "$out/grade-$which"
    echo "$which render $(secs "$bin" render scripts/bloom.glib --size 1024x1024 --backend osmesa -o "$out/$which.png")"
    echo "$which check $(secs "$bin" check scripts/bloom.glib --backend osmesa)"
    echo "$which grade $(secs "$bin" batch "$class" --reference tests/data/grading/blur/blur.glib -o "$out/grade-$which" \
      --size 128x128 --jobs 1 --no-sandbox --backend osmesa)"
  done
done >"$out/times"
# The seconds column aside, the two reports must be the same grades.
if ! diff <(cut -d, -f1-5,7- "$out/grade-A/grades.csv") <(cut -d, -f1-5,7- "$out/grade-B/grades.csv") >/dev/null; then
  echo "bench-two-builds: A and B grade the class differently" >&2; exit 1
fi
python3 - "$out/times" "$runs" <<'PY'
import statistics, sys
rows = [l.split() for l in open(sys.argv[1])]
for work in ("render", "check", "grade"):
    a = statistics.median(float(t) for w, k, t in rows if w == "A" and k == work)
    b = statistics.median(float(t) for w, k, t in rows if w == "B" and k == work)
    print(f"{work:7s} A {a:8.3f} s   B {b:8.3f} s   B/A {b / a:.3f}   (medians of {sys.argv[2]})")
PY
