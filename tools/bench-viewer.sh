#!/usr/bin/env bash
# Does the viewer keep answering while a heavy pass draws? Opens the seed
# bloom (a 23x23 superblur into 512x512, then the composite) at 600x600 in a
# real window under Xvfb and drags uHalfSize around 11 the way a slider drag
# does: a new value every 33 ms for 3 s (through stdin `set`, which takes the
# same path as the panel's slider). Then asks `frames` for the window's frame
# times during the drag, and again after the drag for how long the final
# picture took after the last change. Runs twice in the same go: with slices
# (the default) and with GLIMMER_SLICE_MS=0 (every frame drawn whole, as the
# viewer did before), so the two are compared on the same machine.
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

run() {  # $1: label, $2: GLIMMER_SLICE_MS
  local fifo="$work/in.$1" out="$work/out.$1"
  mkfifo "$fifo"
  DISPLAY=$display GLIMMER_SLICE_MS=$2 "$g" view scripts/bloom.glib --size 600x600 --set uHalfSize=11 \
      < "$fifo" > "$out" 2>/dev/null &
  local viewer=$!
  exec 7> "$fifo"
  sleep 4  # loaded, first picture drawn
  echo frames >&7
  for i in $(seq 45); do
    echo "set uHalfSize 10" >&7; sleep 0.033
    echo "set uHalfSize 11" >&7; sleep 0.033
  done
  echo frames >&7   # the frame times during the drag
  sleep 3
  echo frames >&7   # the final picture's time after the last change
  echo quit >&7
  exec 7>&-
  wait $viewer || true
  echo "$1 (GLIMMER_SLICE_MS=$2):"
  sed -n '2p' "$out" | sed 's/^/  during the drag: /'
  sed -n '3p' "$out" | sed 's/^/  after the drag:  /'
}
run sliced ""
run whole 0
