#!/usr/bin/env bash
# Lessons open and draw as render draws them: a lesson packed into one HTML
# file, opened from disk; a glman folder picked with the page's button, and
# dropped on the page; the picture its Save PNG downloads; a --static
# lesson folder served over HTTP. A lesson whose path would leave its
# folder is refused.
# Usage: tests/web/lessons.sh [DESKTOP_GLIMMER] [WEB_BUILD_DIR]
#        (the module built already; tests/web/page_lib.sh says what is shared)
source "$(dirname "$0")/page_lib.sh"

# A lesson packed into one HTML file opens from disk with no server and no
# file-access flag, and draws its script as render does.
mkdir "$pictures/lesson"
cp tests/data/web/lit_es.* "$pictures/lesson/"
python3 tools/web_lesson.py pack "$pictures/lesson" "$web/src/web" --html "$pictures/lesson.html" --glimmer "$g" >/dev/null
page_dom "file://$pictures/lesson.html" | dom_png > "$pictures/packed.png"
"$g" -q render "$pictures/lesson/lit_es.glib" --size 512x512 -o "$pictures/packed_desktop.png"
echo "  a packed lesson, opened from disk, against render"
[ -s "$pictures/packed.png" ] && same_picture "$pictures/packed.png" "$pictures/packed_desktop.png"
tally $? "the packed lesson did not draw render's picture"

# The same lesson written as a folder with --static and served on
# loopback (python3 -m http.server): its own lesson.json draws render's
# picture. (tests/web/lesson_security.sh serves such a folder too, to
# show what it refuses.)
python3 tools/web_lesson.py pack "$pictures/lesson" "$web/src/web" --static "$pictures/site" --glimmer "$g" >/dev/null
serve "$pictures/site"
site="http://127.0.0.1:$served_port/index.html"
page_dom "$site" | dom_png > "$pictures/static.png"
echo "  a --static lesson folder, served over HTTP, against render"
[ -s "$pictures/static.png" ] && same_picture "$pictures/static.png" "$pictures/packed_desktop.png"
tally $? "the --static lesson served over HTTP did not draw render's picture"

# A user picks a glman classroom folder (script, shaders) with the page's
# folder button (tools/page-pick-folder.mjs sets it as the dialog would):
# the page draws its script, desktop GLSL translated, as render draws it.
# The wire teapot of teapot.glib is left out of the copy: 1-pixel lines
# follow each rasterizer's own rule (360 pixels, PSNR 38.9 with it).
mkdir "$pictures/picked"
sed '/WireTeapot/d' tests/data/glman/teapot.glib > "$pictures/picked/teapot.glib"
cp tests/data/glman/pass.vert tests/data/glman/lit.frag "$pictures/picked/"
"$g" -q render "$pictures/picked/teapot.glib" --size 512x512 -o "$pictures/picked_desktop.png"
echo "  a picked glman folder against render"
mkdir "$pictures/downloads"
NODE_PATH=/usr/share/nodejs node tools/page-pick-folder.mjs "file://$page" "$pictures/picked" "$pictures/picked.png" \
     "$pictures/downloads" >/dev/null 2>"$pictures/picked.err" \
   && same_picture "$pictures/picked.png" "$pictures/picked_desktop.png"
tally $? "the picked folder did not draw render's picture ($(tail -c 300 "$pictures/picked.err"))"
# The same folder dropped on the page (dragged from a file manager).
echo "  a dropped glman folder against render"
NODE_PATH=/usr/share/nodejs node tools/page-pick-folder.mjs --drop "file://$page" "$pictures/picked" \
     "$pictures/dropped.png" >/dev/null 2>&1 \
   && same_picture "$pictures/dropped.png" "$pictures/picked_desktop.png"
tally $? "the dropped folder did not draw render's picture"
# Its Save PNG button downloaded that picture, named after the script.
cmp -s "$pictures/downloads/teapot.png" "$pictures/picked.png"
tally $? "Save PNG did not download the picture as teapot.png ($(ls "$pictures/downloads"))"

# A lesson whose file would leave the page's /user folder is refused as a
# whole, with the reason, and nothing is drawn.
printf '{"files": {"a.glib": "", "../escape.glib": ""}}\n' > "$pictures/hostile.json"
verdict="$(page_dom "file://$page?lesson=file://$pictures/hostile.json" --allow-file-access-from-files |
  grep -o '<p id="verdict"[^<]*')"
grep -q 'data-exit="2"' <<<"$verdict" && grep -Eq 'refused: the path ("|&quot;)\.\./escape\.glib("|&quot;) leaves the folder' <<<"$verdict"
tally $? "a lesson path leaving /user was not refused: $verdict"

# The repository's bloom lesson (scripts/: the seed, the exercises, the
# blur methods) packs as it is (issue 27): every script is checked as the
# page runs it, the shaders and textures its scripts read from beside it
# come along (shaders/, textures/: no "cannot find" in the page), the file
# is at most 3 MB (the module and the lesson gzip-compressed, undone by the
# browser), it opens from disk drawing the seed as render does, and its list
# holds each of the folder's scripts once.
said="$(python3 tools/web_lesson.py pack scripts "$web/src/web" --html "$pictures/bloom-lesson.html" --glimmer "$g" 2>&1)"
bytes="$(stat -c %s "$pictures/bloom-lesson.html" 2>/dev/null || echo 0)"
echo "  the bloom lesson (scripts/) packed: $bytes bytes"
page_dom "file://$pictures/bloom-lesson.html" > "$pictures/bloom-lesson.dom"
dom_png < "$pictures/bloom-lesson.dom" > "$pictures/bloom-lesson.png"
"$g" -q render scripts/bloom.glib --size 512x512 -o "$pictures/bloom_desktop.png"
python3 - "$pictures/bloom-lesson.dom" "$(find scripts -name '*.glib' | wc -l)" <<'PY'
import re, sys
dom = open(sys.argv[1]).read()
options = re.findall(r'<option value="([^"]*)"', dom)
verdict = re.search(r'<[^>]*id="verdict"[^>]*>([^<]*)<', dom)
ok = (verdict and verdict.group(1) == "scripts/bloom.glib: drawn" and len(options) == int(sys.argv[2])
      and len(set(options)) == len(options) and all(o.startswith("/user:scripts/") for o in options))
sys.exit(0 if ok else 1)
PY
[ $? -eq 0 ] && [ "$bytes" -gt 0 ] && [ "$bytes" -le 3000000 ] && same_picture "$pictures/bloom-lesson.png" "$pictures/bloom_desktop.png"
tally $? "the packed bloom lesson (scripts/) is over 3 MB, does not draw the seed, or lists its scripts other than once each: $said"

# A folder with a script that would fail in the page is refused with that
# script's messages (the packer checks every script); with
# --leave-out-failing the others are packed and the failing one is not
# listed. A script reading a file above the folder's parent is refused.
mkdir -p "$pictures/mixed/deep/er"
cp tests/data/web/lit_es.* tests/data/web/broken.* "$pictures/mixed/"
said="$(python3 tools/web_lesson.py pack "$pictures/mixed" "$web/src/web" --static "$pictures/mixed-site" --glimmer "$g" 2>&1)"
code=$?
[ "$code" -eq 2 ] && [[ "$said" == *"broken.glib will not run in the page:"*": error: "* ]] &&
  [[ "$said" == *"1 of 2 scripts will not run in the page"* ]] && [ ! -e "$pictures/mixed-site/lesson.json" ]
tally $? "a lesson with a failing script was not refused with its messages (exit $code): $said"
python3 tools/web_lesson.py pack "$pictures/mixed" "$web/src/web" --static "$pictures/mixed-site" --glimmer "$g" \
    --leave-out-failing >/dev/null 2>&1
python3 -c 'import json, sys
lesson = json.load(open(sys.argv[1]))
sys.exit(0 if lesson["scripts"] == ["lit_es.glib"] and "broken.glib" not in lesson["files"] and "lit_es.frag" in lesson["files"] else 1)' \
  "$pictures/mixed-site/lesson.json" 2>/dev/null
tally $? "--leave-out-failing did not pack the good script alone: $(head -c 300 "$pictures/mixed-site/lesson.json" 2>&1)"
printf 'Vertex ../../../outside.vert\nFragment lit_es.frag\nProgram P\nQuadXY .2 1.\n' > "$pictures/mixed/deep/er/reach.glib"
cp tests/data/web/lit_es.vert "$pictures/outside.vert"
cp tests/data/web/lit_es.frag "$pictures/mixed/deep/er/"
said="$(python3 tools/web_lesson.py pack "$pictures/mixed/deep" "$web/src/web" --static "$pictures/deep-site" --glimmer "$g" 2>&1)"
[[ "$said" == *"reach.glib will not run in the page:"*"outside.vert, outside "*"which a lesson does not carry"* ]]
tally $? "a script reading a file above the folder's parent was packed: $said"

finish
