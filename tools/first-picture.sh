#!/usr/bin/env bash
# The page's first picture as a student meets it (issue 39): each engine
# (Chromium, Firefox ESR, WebKitGTK), a fresh profile every run, a real
# window of 1366x768 outer size on an X server of its own, the seed opened
# two ways: index.html over loopback HTTP (python3 -m http.server) and the
# packed one-file lesson from disk (tools/web_lesson.py pack --html). Prints
# per run the page's own marks (tools/page-engine.mjs --first=WxH): module
# ready, the open (glimmer_view_open), the first frames, the first picture,
# all in ms; then each engine's median first picture. A benchmark: it
# prints figures and judges nothing. Run it on a quiet machine (pause a
# mutation run: touch build-mut/sample/PAUSE).
# Usage: tools/first-picture.sh [RUNS] [ENGINES...]
#   RUNS default 5; ENGINES default chromium firefox webkit.
#   GLIMMER=build/src/app/glimmer WEB=build/web (where the module is built).
#   QUERY=no-translations opens both without the kept translations (what
#   the first picture costs when glslang runs; web_translations.cpp).
set -uo pipefail
cd "$(dirname "$0")/.."
runs="${1:-5}"
shift || true
engines=("$@")
[ "${#engines[@]}" -eq 0 ] && engines=(chromium firefox webkit)
g="${GLIMMER:-build/src/app/glimmer}"
web="${WEB:-build/web}/src/web"
source tests/web/engine_lib.sh  # with_x: an X server of its own; pack_seed_lesson
work="$(mktemp -d)"
pictures="$work"  # with_x keeps its display fifo there
trap 'kill "$server" 2>/dev/null; rm -rf "$work"' EXIT

lesson="$work/lesson"
pack_seed_lesson "$lesson" "$web" "$g" || { echo "first-picture: the lesson could not be packed" >&2; exit 1; }
port=$(python3 -c 'import socket; s = socket.socket(); s.bind(("127.0.0.1", 0)); print(s.getsockname()[1])')
python3 -m http.server "$port" --bind 127.0.0.1 --directory "$web" >/dev/null 2>&1 &
server=$!
sleep 1

printf "%-9s %-7s %4s %8s %8s %8s %8s  %s\n" engine from run module open frames first verdict
for engine in "${engines[@]}"; do
  for from in http disk; do
    url="http://127.0.0.1:$port/index.html"
    [ "$from" = disk ] && url="file://$lesson/lesson.html"
    url="$url${QUERY:+?$QUERY}"
    for ((k = 1; k <= runs; k++)); do
      json="$(NODE_PATH=/usr/share/nodejs with_x timeout 90 node tools/page-engine.mjs "$engine" "$url" "$work" \
                --first=1366x768 2>/dev/null | tail -1)"
      python3 - "$json" "$engine" "$from" "$k" <<'PY' | tee -a "$work/rows"
import json, sys
try:
    r = json.loads(sys.argv[1])
except ValueError:
    r = {"verdict": "no result"}
f = lambda k: "%8s" % (int(r[k]) if isinstance(r.get(k), (int, float)) and r[k] == r[k] else "-")
print("%-9s %-7s %4s %s %s %s %s  %s" % (sys.argv[2], sys.argv[3], sys.argv[4], f("moduleReadyMs"), f("firstOpenMs"),
      f("firstFramesMs"), f("firstPictureMs"), r.get("verdict", r.get("failed", ""))[:40]),
      "| module %s lesson %s kept %s, open at %s, frames at %s" % (f("moduleMs").strip(), f("lessonMs").strip(),
      f("keptMs").strip(), f("firstOpenAtMs").strip(), f("firstFramesAtMs").strip()))
PY
    done
  done
done
echo
python3 - "$work/rows" <<'PY'
import statistics, sys
rows = [l.split() for l in open(sys.argv[1])]
for key in sorted({(r[0], r[1]) for r in rows}):
    firsts = [int(r[6]) for r in rows if (r[0], r[1]) == key and r[6] != "-"]
    print("%-9s %-5s first picture median %s ms (%s)" % (key[0], key[1], statistics.median(firsts) if firsts else "-",
          ", ".join(map(str, sorted(firsts)))))
PY
