#!/usr/bin/env bash
# Does the viewer keep answering while a heavy pass draws? Opens the seed
# bloom (a 23x23 superblur into 512x512, then the composite) at 600x600 in a
# real window under Xvfb and drags uHalfSize around 11 the way a slider drag
# does: a new value every 33 ms for 3 s (through stdin `set`, which takes the
# same path as the panel's slider). After each drag, `frames` gives the
# window's frame times during the drag, and after a pause how long the final
# picture took after the last change. Three drags per run; two runs in the
# same go: with slices (the default) and with GLIMMER_SLICE_MS=0 (every frame
# drawn whole, as the viewer did before), compared on the same machine.
# A second pair of runs drags the panel's real uHalfSize slider with the
# mouse (xdotool, 30 moves a second between the positions of 10 and 11):
# its place, x 752..766 at y 373, is where the panel puts it for the seed at
# 600x600 and --ui-scale 1 (DejaVu Sans at 15 px); another layout needs them changed.
# Usage: tools/bench-viewer.sh [GLIMMER] (default build/src/app/glimmer).
set -euo pipefail
cd "$(dirname "$0")/.."
g="$(realpath "${1:-build/src/app/glimmer}")"
work="$(mktemp -d)"
display=:$((90 + RANDOM % 9))
Xvfb "$display" -screen 0 1400x900x24 >/dev/null 2>&1 &
xvfb=$!
trap 'kill $xvfb 2>/dev/null; rm -rf "$work"' EXIT
sleep 1

run() {  # $1: label, $2: GLIMMER_SLICE_MS, $3: stdin or mouse
  local fifo="$work/in.$1" out="$work/out.$1"
  mkfifo "$fifo"
  DISPLAY=$display GLIMMER_SLICE_MS=$2 "$g" view scripts/bloom.glib --size 600x600 --set uHalfSize=11 \
      < "$fifo" > "$out" 2>/dev/null &
  local viewer=$!
  exec 7> "$fifo"
  sleep 4  # loaded, first picture drawn
  for drag in 1 2 3; do
    echo frames >&7   # starts the count afresh
    if [ "$3" = mouse ]; then
      DISPLAY=$display xdotool mousemove 764 373 mousedown 1
      for i in $(seq 45); do
        DISPLAY=$display xdotool mousemove 752 373; sleep 0.033
        DISPLAY=$display xdotool mousemove 766 373; sleep 0.033
      done
    else
      for i in $(seq 45); do
        echo "set uHalfSize 10" >&7; sleep 0.033
        echo "set uHalfSize 11" >&7; sleep 0.033
      done
    fi
    echo frames >&7   # the frame times during the drag
    [ "$3" = mouse ] && DISPLAY=$display xdotool mouseup 1
    sleep 2
    echo frames >&7   # the final picture's time after the last change
  done
  echo quit >&7
  exec 7>&-
  wait $viewer || true
}
run sliced "" stdin
run whole 0 stdin
run mouse-sliced "" mouse
run mouse-whole 0 mouse
python3 - "$work"/out.{sliced,whole,mouse-sliced,mouse-whole} <<'PY'
import re, statistics, sys
def read(path):
    lines = [l for l in open(path) if l.startswith("frames:")]
    drags = []
    for k in range(3):
        during, after = lines[3 * k + 1], lines[3 * k + 2]
        p95 = float(re.search(r"p95 ([\d.]+) ms", during).group(1))
        final = float(re.search(r"last picture ([\d.]+) ms after", after).group(1))
        drawing = float(re.search(r"\(([\d.]+) ms drawing", after).group(1))
        drags.append((p95, final, drawing))
        print(f"  drag {k + 1}: p95 frame {p95:6.1f} ms; final picture {final:6.1f} ms after the last change "
              f"({drawing:.1f} ms drawing)")
    return [statistics.median(c) for c in zip(*drags)]
for how, (sliced, whole) in (("stdin set", sys.argv[1:3]), ("mouse on the slider", sys.argv[3:5])):
    print(f"== dragged by {how}")
    print("with slices (default):")
    s = read(sliced)
    print("whole frames (GLIMMER_SLICE_MS=0):")
    w = read(whole)
    print(f"median p95 frame while dragging: {s[0]:.1f} ms with slices, {w[0]:.1f} ms whole")
    print(f"final picture after the last change: {s[1]:.1f} ms with slices = {s[1] / w[2]:.2f}x one whole frame "
          f"({w[2]:.1f} ms drawing)")
PY
