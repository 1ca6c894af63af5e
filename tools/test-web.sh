#!/usr/bin/env bash
# The browser build against the desktop build (issue 20), in headless
# Chromium (SwiftShader's WebGL 2, no GPU needed), for people: builds the
# web module once (tools/build-web.sh), then runs each group of checks in
# tests/web/ in turn and sums them. CTest runs the same groups as tests of
# their own (web.build, then web.GROUP), so a failure names its group:
# - check_matches_desktop: every bundled script checked in the page prints
#   exactly what `glimmer check --web` prints, a missing one refused alike;
# - pictures: scripts drawn in the page are render's pictures (ES and
#   translated, --set changes the picture); render-web.sh prints text;
# - lessons: a packed lesson from disk, a picked and a dropped glman folder,
#   Save PNG, a --static folder over HTTP draw render's picture; a lesson
#   path leaving its folder is refused;
# - live_view: sliders, probe, Save sheet and Save file, a broken shader
#   edit, reload and Revert, an unset uniform, no float targets;
# - lesson_security: a lesson is data from the page's own origin, never run;
#   the Content-Security-Policy; the packer takes no link;
# - opening: the page opens drawing the seed; opened from disk where it
#   cannot load its module, it says what to do; stand-ins in the live view;
# - both_shells: the same `glimmer view` commands typed into a window
#   (under Xvfb) and run in the page say the same and save the same
#   pictures (one viewer core, issue 25);
# - hidpi: devicePixelRatio 2 (the panel drawn at the screen's pixels, the
#   box the same size) and a finger on the sliders;
# - layout: at 1366x768 and 1280x720 the picture and the seed's sliders in
#   view, the editor beside them; a long error moves nothing and does not
#   widen the panel; the presentation mode larger, still in view;
# - reload: a reload mid-lesson keeps the picked folder, the script, the
#   file open in the editor and every slider's value;
# - tradeoff: Measure blurs on this machine, clicked: every method of the
#   desktop's `glimmer tradeoff --size 256x256`, its errors the desktop's,
#   real times, the page painting meanwhile (llvmpipe, under Xvfb);
# - watch: a watch in the page is byte for byte the shader hand-edited in the
#   page to write the value, and render --watch's picture; a refusal in its words;
# - engine_chromium, engine_firefox, engine_webkit: the page's checks (the
#   seed drawn as render draws it, Save PNG, a slider and a live edit, a
#   typo kept with the picture, a reload keeping the edit) in each of
#   Chromium, Firefox ESR and WebKitGTK (Safari's engine), under Xvfb.
# tests/web/page_lib.sh holds what the groups share.
# Usage: tools/test-web.sh [DESKTOP_GLIMMER] [WEB_BUILD_DIR]
#        (default build/src/app/glimmer, build-web)
set -uo pipefail
cd "$(dirname "$0")/.."
g="${1:-build/src/app/glimmer}"
web="${2:-build-web}"
tools/build-web.sh "$web" >/dev/null || { echo "web build failed (tools/build-web.sh $web)"; exit 1; }
log="$(mktemp)"
trap 'rm -f "$log"' EXIT
passed=0 failed=0
for group in check_matches_desktop pictures lessons live_view lesson_security opening both_shells hidpi layout reload watch \
             tradeoff engine_chromium engine_firefox engine_webkit; do
  tests/web/$group.sh "$g" "$web" | tee "$log"
  rc=${PIPESTATUS[0]}
  count="$(sed -n "s/^web $group: \([0-9]*\) passed, \([0-9]*\) failed$/\1 \2/p" "$log" | tail -1)"
  if [ -z "$count" ]; then
    # The group stopped before its count (a missing tool, no build): one failure.
    failed=$((failed + 1))
    echo "DIFFERS: tests/web/$group.sh gave no count (exit $rc)"
  else
    read -r p f <<<"$count"
    passed=$((passed + p)) failed=$((failed + f))
    [ "$rc" -eq 0 ] || [ "$f" -gt 0 ] || { failed=$((failed + 1)); echo "DIFFERS: tests/web/$group.sh exit $rc with 0 failed"; }
  fi
done
echo "web: $passed passed, $failed failed"
[ "$failed" -eq 0 ]
