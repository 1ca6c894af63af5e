#!/usr/bin/env bash
# The panel tour in the page (issue 39): every control of the panel, as
# tests/data/panel_tour.txt lists them, pressed, dragged and typed into with
# each engine's real mouse and keys (tools/page-engine.mjs --tour, steps in
# tools/panel-tour.mjs), in Chromium, Firefox ESR and WebKitGTK, each a real
# window on an X server of its own; its effect read back from the core with
# `panel`. The window takes the same tour (test_viewer's PanelTour).
# Usage: tests/web/panel_tour.sh [DESKTOP_GLIMMER] [WEB_BUILD_DIR]
source "$(dirname "$0")/page_lib.sh"
source "$(dirname "$0")/engine_lib.sh"
need_engine Xvfb tools/node_modules/puppeteer-core firefox-esr WebKitWebDriver
serve "$web/src/web"
steps="$(grep -c '^[^#].* | ' tests/data/panel_tour.txt)"
for engine in ${GLIMMER_TOUR_ENGINES:-chromium firefox webkit}; do
  # WebKit reads nothing beside a page opened from disk (engine_webkit.sh): over HTTP.
  url="file://$page"
  [ "$engine" = webkit ] && url="http://127.0.0.1:$served_port/index.html"
  out="$pictures/$engine"
  mkdir -p "$out"
  echo "  the panel tour in $engine ($steps steps)"
  got="$(with_x timeout 400 env GLIMMER_ENGINE_SECONDS=380 node tools/page-engine.mjs "$engine" "$url" "$out" --tour 2>"$out/stderr" | tail -1)"
  python3 -c 'import json, sys; r = json.loads(sys.argv[1]); sys.exit(0 if r["steps"] == int(sys.argv[2]) and not r["failures"] else 1)' \
    "$got" "$steps" 2>/dev/null
  tally $? "$engine: the panel tour: $(python3 -c 'import json, sys; r = json.loads(sys.argv[1]); print(r.get("steps"), "of", sys.argv[2], "steps;", "\n".join(r.get("failures") or [r.get("failed", "")]))' "$got" "$steps" 2>/dev/null || echo "$got") $(tail -3 "$out/stderr")"
done
finish
