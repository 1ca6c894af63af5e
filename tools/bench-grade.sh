#!/usr/bin/env bash
# Grading throughput: a generated class of N submissions graded against the
# solution in tests/data/grading/solution with `glimmer batch --reference`
# (5 settings a submission, sandbox on, --jobs = cores), for several class
# sizes. Prints submissions/second, peak memory (the resident set of the
# parent and its workers together, and of the largest one, sampled every
# 0.1 s) and the report's size. A class mixes what a teacher meets: half
# right, and a sixth each almost right, painted for one setting, blank and
# not compiling (see mk()).
# Usage: [BACKEND=egl-device] tools/bench-grade.sh [GLIMMER] [SIZES...]
# (default osmesa, build/src/app/glimmer, 50 100 200 400).
set -euo pipefail
cd "$(dirname "$0")/.."
g="${1:-build/src/app/glimmer}"
shift || true
sizes=("$@")
backend="${BACKEND:-osmesa}"
[ ${#sizes[@]} -gt 0 ] || sizes=(50 100 200 400)
sol=tests/data/grading/solution
work="$(mktemp -d)"
trap 'rm -rf "$work"' EXIT
mk() {  # mk CLASS_DIR N
  local cls=$1 n=$2 k d
  for k in $(seq 1 "$n"); do
    d="$cls/student$(printf %04d "$k")"
    mkdir -p "$d"
    cp "$sol/st.vert" "$sol/rings.glib" "$sol/rings.frag" "$d/"
    case $((k % 6)) in
      1) sed -i 's/(0.5 + 0.5 \* uTint)/(0.52 + 0.48 * uTint)/' "$d/rings.frag" ;;            # almost right
      2) sed -i 's/6.2831853 \* uFreq/6.2831853 * 6.0/' "$d/rings.frag" ;;                     # painted for the defaults
      3) sed -i 's/gl_FragColor = vec4(mix.*/gl_FragColor = vec4(0.0, 0.0, 0.0, 1.0);/' "$d/rings.frag" ;;  # blank
      4) sed -i 's/float r = /float r = = /' "$d/rings.frag" ;;                                 # does not compile
      *) ;;                                                                                     # right
    esac
  done
}
echo "grading on $(nproc) cores, --backend $backend, 128x128, 5 settings a submission, --jobs $(nproc)"
printf "%8s %9s %8s %8s %16s %16s %10s\n" students seconds subs/s ms/sub "peak RSS all MiB" "largest one MiB" "report MiB"
for n in "${sizes[@]}"; do
  cls="$work/class$n"
  mk "$cls" "$n"
  t0=$(date +%s.%N)
  "$g" -q batch "$cls" --reference "$sol/rings.glib" -o "$work/out$n" \
    --size 128x128 --backend "$backend" --jobs "$(nproc)" --timeout 30 2>/dev/null &
  pid=$!
  peak=0 largest=0
  while kill -0 "$pid" 2>/dev/null; do
    read -r sum one < <(ps -o rss= -p "$pid" --ppid "$pid" | awk '{s += $1; if ($1 > m) m = $1} END {print s + 0, m + 0}')
    [ "$sum" -gt "$peak" ] && peak=$sum
    [ "$one" -gt "$largest" ] && largest=$one
    sleep 0.1
  done
  wait "$pid" || true
  t1=$(date +%s.%N)
  graded=$(($(wc -l < "$work/out$n/grades.csv") - 1))
  [ "$graded" -eq "$n" ] || { echo "only $graded of $n graded" >&2; exit 1; }
  python3 - "$n" "$t0" "$t1" "$peak" "$largest" "$(stat -c %s "$work/out$n/report.html")" <<'PY'
import sys
n, t0, t1, peak, largest, html = int(sys.argv[1]), float(sys.argv[2]), float(sys.argv[3]), int(sys.argv[4]), int(sys.argv[5]), int(sys.argv[6])
s = t1 - t0
print(f"{n:8d} {s:9.2f} {n/s:8.1f} {1000*s/n:8.1f} {peak/1024:16.1f} {largest/1024:16.1f} {html/2**20:10.2f}")
PY
  rm -rf "$cls" "$work/out$n"
done
