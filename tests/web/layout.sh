#!/usr/bin/env bash
# The page's layout on a laptop's screen (issue 27), measured in headless
# Chromium at 1366x768 and 1280x720 (tools/page-layout.mjs): opened with
# nothing asked, the picture and both sliders of the seed bloom (uHalfSize,
# uAdd, in the panel beside the picture) are in the window without
# scrolling, the editor beside them; a broken line 300 characters long
# typed into bloom.frag moves neither the editor nor the canvas and does not
# widen the panel (its error is one line there, cut at its edge), the first
# error shows whole under the canvas, wrapped in its width, the sliders
# still in the window; the presentation mode makes the
# picture and the sliders larger, still in the window, and leaving it
# gives the page back as it was. With GLIMMER_LAYOUT_SHOTS=DIR the
# screenshots (WxH-open.png, -broken.png, -present.png) are kept in DIR.
# Then the same sizes as real windows (issue 39: the outer size, so the page
# gets what is left once the browser's bars are drawn) in Chromium, Firefox
# ESR and WebKitGTK (tools/page-engine.mjs --layout=WxH,
# tools/page-window-layout.mjs): the picture, the sliders and the verdict in
# the window when opened, with a watch on (the panel at its longest: it
# scrolls inside itself) and with an error showing (the panel's error line
# wrapped, not cut), and the watch's buttons not cut at the panel's edge.
# Usage: tests/web/layout.sh [DESKTOP_GLIMMER] [WEB_BUILD_DIR]
#        (the module built already; tests/web/page_lib.sh says what is shared)
source "$(dirname "$0")/page_lib.sh"

mkdir "$pictures/shots"
sizes=(1366x768 1280x720)
echo "  the page at ${sizes[*]}"
measured="$(NODE_PATH=/usr/share/nodejs timeout 600 node tools/page-layout.mjs "file://$page" "$pictures/shots" "${sizes[@]}" 2>&1)"
[ -n "${GLIMMER_LAYOUT_SHOTS:-}" ] && mkdir -p "$GLIMMER_LAYOUT_SHOTS" && cp "$pictures"/shots/*.png "$GLIMMER_LAYOUT_SHOTS/"
# One check: DESCRIPTION, SIZE, a Python condition over that size's
# measures (open, broken, present, after; inside(rect, m) says a rect is in
# m's viewport).
check_layout() {
  python3 - "$measured" "$2" "$3" <<'PY' 2>/dev/null
import json, sys
m = json.loads(sys.argv[1])[sys.argv[2]]
def inside(r, at):
    w, h = at["viewport"]
    return r is not None and r["left"] >= 0 and r["top"] >= 0 and r["right"] <= w + 0.5 and r["bottom"] <= h + 0.5
def same(a, b, keys):
    return a is not None and b is not None and all(abs(a[k] - b[k]) < 0.5 for k in keys)
sys.exit(0 if eval("(" + sys.argv[3] + ")", {"inside": inside, "same": same}, m) else 1)
PY
  tally $? "$2: $1: $(python3 -c '
import json, sys
m = json.loads(sys.argv[1])[sys.argv[2]]
for k, v in m.items():  # each measure on a line, the long message cut
    v["firstErrorText"] = v["firstErrorText"][:100]
    print(" ", k, json.dumps(v))' "$measured" "$2" 2>/dev/null || cut -c1-2000 <<<"$measured")"
}
for size in "${sizes[@]}"; do
  check_layout "the picture (the whole canvas) and the sliders uHalfSize and uAdd must be in the window, no scrolling" "$size" \
    'inside(open["canvas"], open) and inside(open["sliders"]["uAdd"], open) and inside(open["sliders"]["uHalfSize"], open)
     and open["scroll"] == open["viewport"] and open["verdict"] == "scripts/bloom.glib: drawn"'
  check_layout "the editor must be beside the picture, not below it" "$size" \
    'open["editor"] is not None and open["editor"]["left"] >= open["canvas"]["right"] and open["editor"]["top"] < open["canvas"]["bottom"]
     and inside(open["editor"], open)'
  # The picture may shrink to keep the error in the window (the page's
  # cap, bounded by the next check); where it starts, the editor beside it
  # and the panel's width in canvas pixels stay.
  check_layout "a long error must move neither the editor nor the canvas, nor widen the panel (the canvas's width)" "$size" \
    'broken["errors"] == 1 and same(broken["editor"], open["editor"], ["left", "top", "width"])
     and same(broken["canvas"], open["canvas"], ["left", "top"]) and broken["canvas"]["width"] <= open["canvas"]["width"] + 0.5
     and broken["canvasPixels"][0] == open["canvasPixels"][0]'
  check_layout "an error must cost the panel two lines at most (its count, its first line), not its whole message" "$size" \
    'broken["canvas"]["height"] - open["canvas"]["height"] <= 45'
  check_layout "with the error, the sliders must stay in the window" "$size" \
    'inside(broken["sliders"]["uAdd"], broken) and inside(broken["sliders"]["uHalfSize"], broken) and broken["scroll"] == broken["viewport"]'
  # (the column: the canvas's width before the error, which the column keeps)
  check_layout "the first error must show whole, wrapped in the canvas's column, under a count" "$size" \
    'broken["firstErrorText"].startswith("shaders/bloom.frag:13:25: error: \x27notDeclaredXXXXXXXX")
     and broken["firstError"]["right"] <= open["canvas"]["right"] + 20 and broken["firstError"]["height"] > 60
     and broken["count"].startswith("1 error")'
  check_layout "the presentation mode must make the picture and the sliders larger, all in the window" "$size" \
    'present["factor"] > 1.1 and present["canvas"]["width"] > 1.1 * open["canvas"]["width"] and inside(present["canvas"], present)
     and inside(present["sliders"]["uAdd"], present) and inside(present["sliders"]["uHalfSize"], present)
     and present["sliders"]["uAdd"]["height"] > 1.1 * open["sliders"]["uAdd"]["height"]'
  check_layout "leaving the presentation mode must give the page back as it was" "$size" \
    'same(after["canvas"], open["canvas"], ["left", "top", "width", "height"]) and same(after["editor"], open["editor"], ["left", "top", "width"])'
done

# Real windows, each engine (WebKit over HTTP: it reads nothing beside a
# page opened from disk).
source "$(dirname "$0")/engine_lib.sh"
need_engine Xvfb tools/node_modules/puppeteer-core firefox-esr WebKitWebDriver
serve "$web/src/web"
check_window() {  # DESCRIPTION PYTHON-CONDITION
  python3 - "$window_json" "$2" <<'PY' 2>/dev/null
import json, sys
r = json.loads(sys.argv[1])
def inside(x, at):
    w, h = at["viewport"]
    return x is not None and x["left"] >= -0.5 and x["top"] >= -0.5 and x["right"] <= w + 0.5 and x["bottom"] <= h + 0.5
def within(x, box):  # not cut at box's right edge
    return x is not None and x["right"] <= box["right"] + 0.5
sys.exit(0 if eval("(" + sys.argv[2] + ")", {"inside": inside, "within": within, "r": r}) else 1)
PY
  tally $? "$engine $size window: $1: $(python3 -c '
import json, sys
r = json.loads(sys.argv[1])
for k in ("open", "watching", "broken"):
    m = r.get(k) or {}
    print(" ", k, json.dumps({x: m.get(x) for x in ("viewport", "outer", "scroll", "canvas", "controls", "verdict", "verdictText", "errors")}))
print(" ", r.get("failed", ""))' "$window_json" 2>/dev/null || cut -c1-1500 <<<"$window_json")"
}
for engine in chromium firefox webkit; do
  url="file://$page"
  [ "$engine" = webkit ] && url="http://127.0.0.1:$served_port/index.html"
  for size in "${sizes[@]}"; do
    echo "  a real $size window in $engine"
    mkdir -p "$pictures/window-$engine"
    window_json="$(with_x timeout 150 node tools/page-engine.mjs "$engine" "$url" "$pictures/window-$engine" "--layout=$size" \
                   2>"$pictures/window-$engine/stderr" | tail -1)"
    [ -n "${GLIMMER_LAYOUT_SHOTS:-}" ] && cp "$pictures/window-$engine"/*.png "$GLIMMER_LAYOUT_SHOTS/" 2>/dev/null
    w="${size%x*}" h="${size#*x}"
    check_window "the window's outer size must be $size (a real window, not a viewport)" \
      "'failed' not in r and abs(r['open']['outer'][0] - $w) <= 2 and abs(r['open']['outer'][1] - $h) <= 2"
    check_window "opened: the picture, the sliders uHalfSize and uAdd and the verdict must be in the window" \
      "all(inside(r['open'][k], r['open']) for k in ('canvas', 'verdict')) and inside(r['open']['controls']['uAdd'], r['open'])
       and inside(r['open']['controls']['uHalfSize'], r['open']) and r['open']['verdictText'] == 'scripts/bloom.glib: drawn'"
    check_window "with a watch on: the picture, both sliders and the verdict still in the window; Watch, Stop and Own range not cut at the panel's edge" \
      "r['watching']['said'].startswith('watch bloom.frag:12 rgbblur') and all(inside(r['watching'][k], r['watching']) for k in ('canvas', 'verdict'))
       and inside(r['watching']['controls']['uAdd'], r['watching']) and inside(r['watching']['controls']['uHalfSize'], r['watching'])
       and all(within(r['watching']['controls'][k], r['watching']['canvas']) for k in ('Watch button', 'Stop', 'Own range'))"
    check_window "with an error: the picture, both sliders, the verdict and the panel's error line (wrapped, not cut) in the window" \
      "r['broken']['errors'] == 1 and all(inside(r['broken'][k], r['broken']) for k in ('canvas', 'verdict'))
       and inside(r['broken']['controls']['Error 1'], r['broken']) and within(r['broken']['controls']['Error 1'], r['broken']['canvas'])
       and r['broken']['controls']['Error 1']['height'] > 20 and inside(r['broken']['controls']['uAdd'], r['broken'])
       and inside(r['broken']['controls']['uHalfSize'], r['broken']) and r['broken']['verdictText'] == 'scripts/bloom.glib: errors'"
  done
done

finish
