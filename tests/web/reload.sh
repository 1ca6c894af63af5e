#!/usr/bin/env bash
# A reload in the middle of a lesson loses nothing (issue 27): a student
# picks a folder (the bloom lesson: scripts, shaders, textures), draws its
# seed, drags both sliders, opens bloom.frag and types into it; the page is
# reloaded (tools/page-reload.mjs) and must come back with the same folder
# (its scripts listed), the same script drawn, the same file open with the
# typed text, the same slider values and the same picture. "Close folder"
# then goes back to the lesson's own scripts, with the sliders at the
# script's values.
# Usage: tests/web/reload.sh [DESKTOP_GLIMMER] [WEB_BUILD_DIR]
#        (the module built already; tests/web/page_lib.sh says what is shared)
source "$(dirname "$0")/page_lib.sh"

mkdir -p "$pictures/folder/bloom-lesson"
cp -r scripts shaders "$pictures/folder/bloom-lesson/"
mkdir "$pictures/folder/bloom-lesson/textures"
cp textures/grid.bmp "$pictures/folder/bloom-lesson/textures/"
echo "  a picked folder, its seed's sliders moved and a shader edited, then a reload"
states="$(NODE_PATH=/usr/share/nodejs timeout 300 node tools/page-reload.mjs "file://$page" "$pictures/folder/bloom-lesson" \
            scripts/bloom.glib shaders/bloom.frag uAdd=0.5 uHalfSize=0.3 2>&1)"
check_reload() {  # DESCRIPTION PYTHON-CONDITION over the states (before, after, closed)
  python3 -c 'import json, sys; r = json.loads(sys.argv[1]); sys.exit(0 if eval("(" + sys.argv[2] + ")", {}, r) else 1)' \
    "$states" "$2" 2>/dev/null
  tally $? "$1: $(python3 -c '
import json, sys
for k, v in json.loads(sys.argv[1]).items():
    v["picture"] = "%d characters" % len(v["picture"]); v["scripts"] = v["scripts"][:3]
    print(" ", k, json.dumps(v))' "$states" 2>/dev/null || cut -c1-2000 <<<"$states")"
}
check_reload "before the reload, the picked folder's seed must be drawn with both sliders moved and the edit typed" \
  'before["script"] == "/user:scripts/bloom.glib" and before["verdict"] == "scripts/bloom.glib: drawn"
   and before["values"]["uAdd"] not in ("", "0") and before["values"]["uHalfSize"] not in ("", "0")
   and before["shown"] == "shaders/bloom.frag" and before["typed"]'
check_reload "after the reload, the folder must be back: its scripts listed as before" \
  'after["scripts"] == before["scripts"] and any(s.startswith("/user:") for s in after["scripts"])'
check_reload "a picked folder's scripts are labelled as the student's own (yours:), the bundled lesson's not" \
  'before["labels"][0] == "yours: scripts/bloom.glib" and closed["labels"][0] == "scripts/bloom.glib"'
check_reload "after the reload, the same script must be chosen and drawn" \
  'after["script"] == before["script"] and after["verdict"] == before["verdict"]'
check_reload "after the reload, the same file must be open in the editor, with the typed text" \
  'after["shown"] == before["shown"] and after["typed"]'
check_reload "after the reload, every slider must have its value" 'after["values"] == before["values"]'
check_reload "after the reload, the watch must be on again (issue 39)" \
  'before["watch"] == "bloom.frag:12 rgbblur" and after["watch"] == before["watch"]'
check_reload "Close folder: the lesson's own seed has no watch (the watch was the folder's script's)" 'closed["watch"] == ""'
check_reload "after the reload, the picture must be the same" \
  'after["picture"].startswith("data:image/png") and after["picture"] == before["picture"]'
check_reload "Close folder must go back to the lesson's own scripts, the seed at its own values" \
  'not any(s.startswith("/user:") for s in closed["scripts"]) and closed["script"] == "/lesson:scripts/bloom.glib"
   and closed["values"] == {"uAdd": "0", "uHalfSize": "0"}'

finish
