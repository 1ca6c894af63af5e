#!/usr/bin/env bash
# Checks on the lent GPU machine (issue 36) that grading, batch and the
# watch never depend on the machine: one line per check, exit 1 on any
# difference.
#
#   Here (llvmpipe), once per change:   tools/gpu-check.sh --reference .gl/ref
#       grades the generated class (tools/grading-class.py) with --jobs 2,
#       sandbox on and off, and keeps the rows in .gl/ref/ (carried with .gl;
#       tools/gpu-bundle.sh keeps it).
#   There:  . .gl/env.sh && tools/gpu-check.sh [ROUNDS]
#       1. the render tests on the GPU (.gl/bin/test_render with
#          GLIMMER_TEST_BACKENDS=egl-device): pixels against the CPU's
#          references, the watch's GPU counts and picture against the CPU's
#          (the tests that compare the two CPU backends, or the desktop with
#          OpenGL ES, need llvmpipe and are left out);
#       2. plain batch of every script of the repository, three times over
#          (several hundred jobs) at --jobs 16: each PNG byte-identical to
#          `glimmer render` of the same script on the same GPU, and a script
#          fails in batch exactly when it fails in render;
#       3. glimmer-bench at BENCH_SIZES (default 512 1920): its figures,
#          printed (not checked);
#       4. the class graded on the GPU at --jobs 1, 4, 8, 16, sandbox on, and
#          8, 16 with --no-sandbox (MODES="8 sandbox,16 no-sandbox" picks, a
#          blank MODES none), ROUNDS times each (default 1): every row's
#          verdict and score equal llvmpipe's of the same mode.
# The class goes last: its submissions that never end are killed, and on
# NVIDIA a process killed while drawing may stay in the driver's lock for
# minutes, holding every new context on the machine (seen on the H200: the
# batch of step 2 then waited behind it). A check that starts with such a
# process on the machine says so.
# Needs python3 (the class) and the .gl bundle of tools/gpu-bundle.sh.
set -uo pipefail
cd "$(dirname "$0")/.."
G="${GLIMMER:-.gl/bin/glimmer}"
work="$(mktemp -d)"
trap 'rm -rf "$work"' EXIT
rows() {  # rows GRADES.CSV: student,verdict,score sorted
  python3 -c 'import csv,sys
for r in sorted(csv.DictReader(open(sys.argv[1], encoding="utf-8")), key=lambda r: r["student"]):
    print(r["student"], r["verdict"], r["score"], sep=",")' "$1"
}
if [ "${1:-}" = "--reference" ]; then
  ref="${2:?tools/gpu-check.sh --reference DIR}"
  mkdir -p "$ref"
  python3 tools/grading-class.py "$work/c" --grade "$G" --jobs 2 -o "$work/sb" >/dev/null
  rows "$work/sb/grades.csv" > "$ref/sandbox.rows"
  python3 tools/grading-class.py "$work/c" --grade "$G" --jobs 2 --no-sandbox -o "$work/nosb" >/dev/null
  rows "$work/nosb/grades.csv" > "$ref/no-sandbox.rows"
  wc -l "$ref"/*.rows
  exit 0
fi
rounds="${1:-1}"
ref=.gl/ref
backend="${BACKEND:-egl-device}"
failed=0
say() { printf '%-4s %s\n' "$1" "$2"; [ "$1" = ok ] || failed=1; }
nvidia-smi --query-gpu=name,driver_version --format=csv,noheader 2>/dev/null | sed 's/^/gpu: /'
stuck() {  # processes in uninterruptible sleep in the NVIDIA driver
  ps -eo pid,stat,wchan:32,args 2>/dev/null | awk '$2 ~ /^D/ && $3 ~ /^os_/'
}
if [ -n "$(stuck)" ]; then
  echo "note: processes are stuck in the GPU driver; every new context waits behind them:"; stuck | sed 's/^/    /'
fi
# 1. The render tests on the GPU.
if [ -x .gl/bin/test_render ]; then
  GLIMMER_TEST_BACKENDS="$backend" timeout 300 .gl/bin/test_render \
    --gtest_filter='-Backends.*:*OnEs*:BuiltinFeed.OnOpenGlEs*' > "$work/render-tests.log" 2>&1
  if [ $? -eq 0 ]; then say ok "render tests on $backend: $(grep -o '[0-9]* tests\? from [0-9]* test suites\? ran' "$work/render-tests.log")"
  else say FAIL "render tests on $backend:"; grep -E '^\[  FAILED|Failure' "$work/render-tests.log" | head -12 | sed 's/^/    /'; fi
fi
# 2. batch against render, several hundred jobs at --jobs 16.
find scripts tests/data -name '*.glib' | sort > "$work/list"
n=$(wc -l < "$work/list")
mkdir -p "$work/b" "$work/r"
"$G" -q batch $(cat "$work/list" "$work/list" "$work/list") -o "$work/b" --size 256x256 --jobs 16 \
  --backend "$backend" --timeout 30 --report "$work/b.jsonl" > /dev/null 2>&1
python3 - "$work" "$G" "$backend" <<'PY'
import json, os, subprocess, sys
work, g, backend = sys.argv[1:4]
lines = [json.loads(l) for l in open(f"{work}/b.jsonl", encoding="utf-8")]
rendered, bad, varies = {}, [], set()
for l in lines:
    s = l["script"]
    if s not in rendered:
        pngs = []
        for k in range(2):  # twice: a script that reads the clock (Timer) draws another picture each time
            png = f"{work}/r/{len(rendered)}-{k}.png"
            r = subprocess.run([g, "-q", "render", s, "-o", png, "--size", "256x256", "--backend", backend],
                               capture_output=True, timeout=120)
            pngs.append(png if r.returncode == 0 and os.path.exists(png) else None)
        if pngs[0] and pngs[1] and open(pngs[0], "rb").read() != open(pngs[1], "rb").read():
            varies.add(s)
        rendered[s] = pngs[0]
    if s in varies:
        continue
    ref = rendered[s]
    out = l["output"]
    if (ref is None) != (out is None):
        bad.append(f"{s}: render {'failed' if ref is None else 'drew'}, batch {'failed' if out is None else 'drew'}: "
                   + l["diagnostics"].strip().splitlines()[-1:][0] if l["diagnostics"].strip() else s)
    elif ref and open(ref, "rb").read() != open(out, "rb").read():
        bad.append(f"{s}: the batch PNG differs from render's")
drew = sum(1 for l in lines if l["output"])
if bad:
    print(f"DIFF batch vs render: {len(lines)} jobs ({len(rendered)} scripts x 3), {len(bad)} differ")
    for b in bad[:15]: print("    " + b)
    sys.exit(1)
print(f"ok   batch vs render: {len(lines)} jobs ({len(rendered)} scripts x 3) at --jobs 16, {drew} PNGs, each byte-identical to render's but for {len(varies)} scripts whose own renders differ (the clock); the rest fail in both")
PY
[ $? -eq 0 ] || failed=1
# 3. The benchmark's figures (the watch among them).
for size in ${BENCH_SIZES:-512 1920}; do
  [ -x .gl/bin/glimmer-bench ] && .gl/bin/glimmer-bench --backend "$backend" --size "$size" --repeat 5 2>&1 | sed "s/^/bench $size: /" | head -40
done
# 4. The class, last (see the top).
python3 tools/grading-class.py "$work/c" >/dev/null
for round in $(seq 1 "$rounds"); do
  IFS=, read -ra modes <<< "${MODES-1 sandbox,4 sandbox,8 sandbox,16 sandbox,8 no-sandbox,16 no-sandbox}"
  for mode in "${modes[@]}"; do
    set -- $mode
    [ $# -eq 2 ] || continue  # a blank MODES: no class
    extra=(); [ "$2" = no-sandbox ] && extra=(--no-sandbox)
    out="$work/g-$1-$2"
    t0=$(date +%s.%N)
    python3 tools/grading-class.py "$work/c" --grade "$G" --jobs "$1" --backend "$backend" "${extra[@]}" -o "$out" \
      > "$out.log" 2>&1
    t=$(python3 -c "import time,sys; print(f'{time.time()-float(sys.argv[1]):.1f}')" "$t0")
    if [ ! -f "$out/grades.csv" ]; then say FAIL "class --jobs $1 $2 (round $round): no grades.csv"; tail -5 "$out.log"; continue; fi
    d=$(diff <(rows "$out/grades.csv") "$ref/$2.rows")
    if [ -z "$d" ]; then say ok "class --jobs $1 $2 (round $round): $(wc -l < "$ref/$2.rows") rows equal llvmpipe's, ${t} s"
    else say DIFF "class --jobs $1 $2 (round $round), ${t} s: (< GPU, > llvmpipe)"; echo "$d" | sed 's/^/    /' | head -20
         grep -v ',pass,' "$out/grades.csv" | cut -c1-300 | sed 's/^/    row: /' | head -12; fi
  done
done
[ "$failed" = 0 ] && echo "gpu-check: every check passed" || echo "gpu-check: some checks FAILED"
exit "$failed"
