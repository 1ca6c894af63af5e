#!/usr/bin/env bash
# Throughput of `glimmer batch` against one `glimmer render` process per
# script, on the same machine in the same run: N small classroom-style
# scripts (tests/data/glman, the seed bloom) at 128x128, rendered both ways.
# Usage: tools/bench-batch.sh [GLIMMER] [COPIES] (default build/src/app/glimmer, 3).
set -euo pipefail
cd "$(dirname "$0")/.."
g="${1:-build/src/app/glimmer}"
copies="${2:-3}"
work="$(mktemp -d)"
trap 'rm -rf "$work"' EXIT
list="$work/list.txt"
for c in $(seq "$copies"); do
  for s in tests/data/glman/{sphere_ortho,quad_texture,teapot,cone_cylinder_disk,wire_shapes,flat_smooth,glbegin,quadbox}.glib scripts/bloom.glib; do
    echo "$s" >> "$list"
  done
done
n=$(wc -l < "$list")
t0=$(date +%s.%N)
i=0
while read -r s; do
  i=$((i + 1))
  "$g" -q render "$s" --size 128x128 --backend osmesa -o "$work/one_$i.png" 2>/dev/null || true
done < "$list"
t1=$(date +%s.%N)
"$g" -q batch --list "$list" -o "$work/batch" --size 128x128 --backend osmesa --jobs "$(nproc)" 2>/dev/null || true
t2=$(date +%s.%N)
python3 - "$n" "$t0" "$t1" "$t2" <<'PY'
import sys
n, t0, t1, t2 = int(sys.argv[1]), *map(float, sys.argv[2:])
one, batch = t1 - t0, t2 - t1
print(f"{n} scripts at 128x128 on {__import__('os').cpu_count()} cores")
print(f"one render process per script: {one:7.2f} s  ({1000*one/n:6.1f} ms a script)")
print(f"glimmer batch --jobs nproc:    {batch:7.2f} s  ({1000*batch/n:6.1f} ms a script)")
print(f"throughput ratio: {one/batch:.2f}x")
PY
