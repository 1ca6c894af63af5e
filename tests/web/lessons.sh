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
python3 tools/web_lesson.py pack "$pictures/lesson" "$web/src/web" --html "$pictures/lesson.html" >/dev/null
page_dom "file://$pictures/lesson.html" | dom_png > "$pictures/packed.png"
"$g" -q render "$pictures/lesson/lit_es.glib" --size 512x512 -o "$pictures/packed_desktop.png"
echo "  a packed lesson, opened from disk, against render"
[ -s "$pictures/packed.png" ] && same_picture "$pictures/packed.png" "$pictures/packed_desktop.png"
tally $? "the packed lesson did not draw render's picture"

# The same lesson written as a folder with --static and served on
# loopback (python3 -m http.server): its own lesson.json draws render's
# picture. (tests/web/lesson_security.sh serves such a folder too, to
# show what it refuses.)
python3 tools/web_lesson.py pack "$pictures/lesson" "$web/src/web" --static "$pictures/site" >/dev/null
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
     "$pictures/downloads" >/dev/null 2>&1 \
   && same_picture "$pictures/picked.png" "$pictures/picked_desktop.png"
tally $? "the picked folder did not draw render's picture"
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

finish
