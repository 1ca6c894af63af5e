#!/usr/bin/env bash
# The browser build against the desktop build (issue 20), in headless
# Chromium (SwiftShader's WebGL 2, no GPU needed):
# - every bundled script checked in the page prints exactly the diagnostics
#   and exit status that the desktop's `glimmer check --web` prints (shaders
#   translated for WebGL 2 in both), and a missing script is refused the
#   same way;
# - a script drawn in the page is the picture `glimmer render` draws of it,
#   within what two rasterizers may differ by: an ES scene at its default
#   and with a value set as --set sets it (which must change the picture),
#   the seed bloom and a compatibility scene through the page's translation;
# - a packed lesson opens from disk; a picked glman folder draws; a hostile
#   lesson is refused; a lesson is data from the page's own origin, never
#   run (a data: link, a script, another origin), and the page and the
#   packed page keep a Content-Security-Policy;
# - the live view's sliders, moved with the mouse, redraw only the passes
#   they reach and give render's picture with --set; a broken shader edit
#   shows its error and keeps the picture and the values.
# Builds the web module first (tools/build-web.sh).
# Usage: tools/test-web.sh [DESKTOP_GLIMMER] [WEB_BUILD_DIR]
#        (default build/src/app/glimmer, build-web)
set -uo pipefail
cd "$(dirname "$0")/.."
g="${1:-build/src/app/glimmer}"
web="${2:-build-web}"
tools/build-web.sh "$web" >/dev/null || { echo "web build failed (tools/build-web.sh $web)"; exit 1; }
page="$(realpath "$web")/src/web/index.html"
profile="$(mktemp -d)"
trap 'rm -rf "$profile"' EXIT
passed=0 failed=0
# Counts one check: STATUS (0 passed) and what differs when it did not.
tally() {
  if [ "$1" -eq 0 ]; then passed=$((passed + 1)); else failed=$((failed + 1)); echo "DIFFERS: $2"; fi
}
# The DOM of the page at URL once it has run (SwiftShader's WebGL 2, virtual
# time); further arguments are Chromium flags: --allow-file-access-from-files
# where the page reads files beside it (a packed lesson must open without).
# 180 s: on two cores shared with a build, the 7 MB packed lesson once took
# past a minute to start (a killed Chromium dumps nothing).
page_dom() {
  # Virtual time runs ahead while the module compiles off the main thread,
  # so on a loaded machine a dump may come before the page is ready
  # (data-ready on the body): then it is taken again, up to three times.
  local dom try
  for try in 1 2 3; do
    dom="$(timeout 180 chromium --headless=new --no-sandbox --user-data-dir="$profile" --use-angle=swiftshader \
      --enable-unsafe-swiftshader --virtual-time-budget=10000 "${@:2}" --dump-dom "$1" 2>/dev/null)"
    grep -q 'data-ready="1"' <<<"$dom" && break
  done
  printf '%s\n' "$dom"
}
# What the page shows for ?QUERY (check=PATH, render=PATH...): "EXIT\nDIAGNOSTICS", read from the DOM.
in_browser() {  # QUERY, e.g. check=PATH
  page_dom "file://$page?$1" --allow-file-access-from-files |
    python3 -c '
import html, re, sys
dom = sys.stdin.read()
exit_ = re.search(r"id=\"verdict\" data-exit=\"(\d+)\"", dom)
diag = re.search(r"<pre id=\"diagnostics\">(.*?)</pre>", dom, re.S)
print(exit_.group(1) if exit_ else "no-result")
# the text only: each "file:line:col:" line is a link to the editor (a span)
sys.stdout.write(html.unescape(re.sub(r"<[^>]+>", "", diag.group(1))) if diag else "")'
}
# The page's Check is `glimmer check --web`: read, plan, read the files and
# translate every shader, with no GL, so the two must print the same bytes:
# every bundled script, the web test scripts (one with a geometry shader
# WebGL 2 lacks, one with a shader error) and a missing script.
for script in $(find scripts tests/data/web -name '*.glib' | sort) scripts/no_such_script.glib; do
  want="$( { "$g" check --web "$script" 2>&1 >/dev/null; echo "exit $?" >&3; } 3>&1 )"
  desktop_exit="$(tail -1 <<<"$want" | sed 's/exit //')"
  desktop_diags="$(sed '$d' <<<"$want")"
  got="$(in_browser "check=$script")"
  web_exit="$(head -1 <<<"$got")"
  web_diags="$(sed '1d' <<<"$got")"
  if [ "$web_exit" = "$desktop_exit" ] && [ "$web_diags" = "$desktop_diags" ]; then
    passed=$((passed + 1))
  else
    failed=$((failed + 1))
    echo "DIFFERS: $script (desktop exit $desktop_exit, page exit $web_exit)"
    diff <(echo "$desktop_diags") <(echo "$web_diags") | head -20
  fi
done

# The page's picture of a script as a PNG file, through the project's own
# command for it (the script's folder handed to the page as a lesson).
page_picture() {
  WEB_BUILD="$web" tools/render-web.sh "$1" --size "$2" ${3:+--set "$3"} -o "$4" >/dev/null 2>&1
  [ -s "$4" ]
}
# Two rasterizers (llvmpipe, SwiftShader) agree except where a pixel centre
# lies on a triangle's edge or a shader's step() sits on its threshold: such
# pixels may go either way, at full size. So the bound is on how many
# differ by more than 2% (5 steps of 255): at most 0.1% of the picture,
# and PSNR at least 40 dB. Measured for lit_es.glib at 256x256: 26 pixels
# (0.04%), PSNR 44.3 dB.
same_picture() {
  local over psnr pixels
  over=$(compare -metric AE -fuzz 2% "$1" "$2" null: 2>&1)
  psnr=$(compare -metric PSNR "$1" "$2" null: 2>&1)
  pixels=$(identify -format '%[fx:w*h]' "$1")
  echo "    $over of $pixels pixels differ by more than 2%, PSNR $psnr dB"
  python3 -c "import sys; o, p, n = float(sys.argv[1]), sys.argv[2], float(sys.argv[3]); \
sys.exit(0 if o <= n / 1000 and (p == 'inf' or float(p) >= 40) else 1)" "$over" "$psnr" "$pixels"
}
pictures="$(mktemp -d)"
trap 'rm -rf "$profile" "$pictures"' EXIT
# An ES scene (drawn as written) and the seed bloom and a glman classroom
# scene (desktop GLSL, translated in the page by glslang and SPIRV-Cross).
# The seed bloom at its grid texture's own size, 512x512: at 256x256 the
# 2:1 minification samples the grid exactly between texels, where the two
# rasterizers may each take either neighbour (948 one-pixel grid-line
# edges, 1.4%, PSNR 49.7 dB: the same class of tie as an edge on a pixel
# centre, but over a whole line).
# Uniform initialisers (`uniform float uY0 = 1.;`), which GLSL ES 3.00 has
# not, set by the page itself (issue 31).
for case in "tests/data/web/lit_es.glib||256x256" "tests/data/web/lit_es.glib|uStripes=3|256x256" \
            "scripts/bloom.glib|uAdd=2|512x512" "tests/data/web/compat_scene.glib||256x256" \
            "tests/data/web/uniform_init.glib||64x64"; do
  IFS='|' read -r script sets size <<<"$case"
  desk="$pictures/desktop.png" shot="$pictures/page.png"
  args=(); [ -n "$sets" ] && args=(--set "$sets")
  "$g" -q render "$script" --size "$size" "${args[@]}" -o "$desk"
  echo "  page against render: $script ${sets:-(defaults)} at $size"
  if page_picture "$script" "$size" "$sets" "$shot" && same_picture "$shot" "$desk"; then
    passed=$((passed + 1))
  else
    failed=$((failed + 1))
    echo "DIFFERS: $script drawn in the page ${sets:+with $sets }is not render's picture"
  fi
  [ "$script" = tests/data/web/lit_es.glib ] && cp "$shot" "$pictures/page_${sets:-default}.png" 2>/dev/null
done
# The set value reached the picture: the two page pictures differ.
[ "$(compare -metric AE "$pictures/page_default.png" "$pictures/page_uStripes=3.png" null: 2>&1)" -gt 1000 ]
tally $? "uStripes=3 did not change the page's picture"

# render-web.sh prints the page's messages as glimmer render does: text,
# not the page's markup around each file:line:col (issue 31).
said="$(WEB_BUILD="$web" tools/render-web.sh tests/data/web/broken.glib -o "$pictures/broken.png" 2>&1 >/dev/null)"
[[ "$said" == *": error: "* && "$said" != *"<"*">"* ]]
tally $? "render-web.sh printed markup or no error for broken.glib: $said"

# A lesson packed into one HTML file opens from disk with no server and no
# file-access flag, and draws its script as render does.
mkdir "$pictures/lesson"
cp tests/data/web/lit_es.* "$pictures/lesson/"
python3 tools/web_lesson.py pack "$pictures/lesson" "$web/src/web" --html "$pictures/lesson.html" >/dev/null
page_dom "file://$pictures/lesson.html" |
  python3 -c '
import base64, re, sys
m = re.search(r"data-png=\"data:image/png;base64,([^\"]*)\"", sys.stdin.read())
sys.stdout.buffer.write(base64.b64decode(m.group(1)) if m else b"")' > "$pictures/packed.png"
"$g" -q render "$pictures/lesson/lit_es.glib" --size 512x512 -o "$pictures/packed_desktop.png"
echo "  a packed lesson, opened from disk, against render"
[ -s "$pictures/packed.png" ] && same_picture "$pictures/packed.png" "$pictures/packed_desktop.png"
tally $? "the packed lesson did not draw render's picture"

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

# The live view, as a student uses it (tools/page-live-view.mjs): the
# seed bloom with the desktop's panel beside it; each slider dragged with
# the mouse redraws only the passes it reaches (uAdd: the Bloom pass, 1;
# uHalfSize: the SuperBlur pass and the Bloom pass reading it, 0 and 1) and
# gives render's picture with --set at the value the slider shows; then a
# typo typed into bloom.frag in the page's editor is one error at its line
# and column, marked on that line, and the picture and the slider values
# stay; a click on the error goes to it; the edit survives a reload of the
# page; Revert brings the file back and the error goes.
mkdir "$pictures/live"
echo "  the live view: sliders, a broken shader edit"
live="$(SHEET=uAdd=0,2,4 PROBE=100,200 NODE_PATH=/usr/share/nodejs node tools/page-live-view.mjs "file://$page" scripts/bloom.glib \
          shaders/bloom.frag 13 "$pictures/live" uAdd=0.5 uHalfSize=0.3 2>&1)"
field() { python3 -c 'import json, sys; r = json.loads(sys.argv[1]); print(eval(sys.argv[2], {}, r))' "$live" "$1" 2>/dev/null; }
add="$(field 'sliders[0]["value"]')" half="$(field 'sliders[1]["value"]')"
[ "$(field 'sliders[0]["drawn"]')" = "1" ] && [ "$(field 'sliders[1]["drawn"]')" = "0 1" ]
tally $? "the passes a slider redrew (uAdd: want 1, uHalfSize: want 0 1): $live"
"$g" -q render scripts/bloom.glib --size 512x512 --set "uAdd=$add" -o "$pictures/live_add.png"
"$g" -q render scripts/bloom.glib --size 512x512 --set "uAdd=$add" --set "uHalfSize=$half" -o "$pictures/live_half.png"
for pair in "slider-uAdd.png|live_add.png|uAdd=$add" "slider-uHalfSize.png|live_half.png|uAdd=$add uHalfSize=$half"; do
  IFS='|' read -r shot desk what <<<"$pair"
  if [ -n "$add" ] && [ "$add" != 0 ] && [ -n "$half" ] && [ "$half" != 0 ] &&
     same_picture "$pictures/live/$shot" "$pictures/$desk"; then
    passed=$((passed + 1))
  else
    failed=$((failed + 1))
    echo "DIFFERS: the live view after its slider ($what) is not render's picture with --set"
  fi
done
# The probe (the viewer core's, as the desktop's): ticked in the panel, the
# pointer on pixel (100, 200), its text gives that pixel of render's picture
# (issue 25: the page's probe did nothing).
probe="$(field 'probe')"
python3 - "$probe" "$pictures/live_half.png" <<'PY'
import re, subprocess, sys
m = re.match(r"\(100, 200\) of screen: r (\S+)  g (\S+)  b (\S+)  a (\S+)$", sys.argv[1])
px = subprocess.run(["convert", sys.argv[2], "-crop", "1x1+100+200", "-depth", "8", "txt:-"], capture_output=True, text=True).stdout
want = [int(v) / 255 for v in re.search(r"\((\d+),(\d+),(\d+)", px.splitlines()[-1]).groups()]
sys.exit(0 if m and all(abs(float(g) - w) <= 0.02 for g, w in zip(m.groups(), want)) else 1)
PY
tally $? "the page's probe at (100, 200) is not render's pixel there: '$probe'"
# Save sheet (uAdd 0, 2, 4 with uHalfSize where its slider left it) is
# `glimmer sheet`'s, title and labels included.
"$g" -q sheet scripts/bloom.glib --vary uAdd=0,2,4 --set "uHalfSize=$half" --size 512x512 -o "$pictures/live_sheet.png"
echo "  the page's Save sheet against glimmer sheet"
[ -s "$pictures/live/sheet.png" ] && same_picture "$pictures/live/sheet.png" "$pictures/live_sheet.png"
tally $? "the page's sheet is not glimmer sheet's"
want="shaders/bloom.frag:13:52: error: 'undeclaredTypo': undeclared identifier"
check_live() {  # DESCRIPTION PYTHON-CONDITION over the page's states
  python3 -c 'import json, sys; r = json.loads(sys.argv[1]); sys.exit(0 if eval("(" + sys.argv[2] + ")", {}, r) else 1)' \
    "$live" "$2" 2>/dev/null
  tally $? "$1: $(cut -c1-2000 <<<"$live")"
}
# Save file, with no folder to write into, downloads the edited script.
python3 -c 'import sys; sys.exit(open(sys.argv[1]).read() != open(sys.argv[2]).read() + "\n# saved from the page\n")' \
  "$pictures/live/downloads/bloom.glib" scripts/bloom.glib 2>/dev/null
tally $? "Save file did not download the edited bloom.glib ($(ls "$pictures/live/downloads" 2>&1))"
check_live "a download keeps the edit in the browser until it is saved or reverted" \
  "saved['kept'] == 1 and 'downloaded' in saved['note']"
check_live "a typo typed into bloom.frag must be one error, '$want', marked on line 13 of the editor, the value kept" \
  "broken['exit'] == 1 and broken['errors'] == 1 and \"$want\" in broken['diagnostics'] and broken['value'] == '$add'
   and broken['shown'] == 'shaders/bloom.frag' and broken['markedLines'] == '13'
   and \"'undeclaredTypo': undeclared identifier\" in broken['message']"
cmp -s "$pictures/live/broken.png" "$pictures/live/slider-uHalfSize.png"
tally $? "the broken edit did not keep the last good picture"
check_live "clicking the error in the diagnostics must open bloom.frag at line 13" \
  "clicked['shown'] == 'shaders/bloom.frag' and clicked['cursorLine'] == 13"
check_live "the typed edit must survive a reload of the page" \
  "'undeclaredTypo' in reloaded['text'] and reloaded['errors'] == 1 and reloaded['markedLines'] == '13'"
check_live "Revert must bring back the file, clear the error and keep nothing" \
  "restored['exit'] == 0 and restored['errors'] == 0 and restored['kept'] == 0 and 'undeclaredTypo' not in restored['text']"

# A uniform the shaders read and the script never sets (issue 19): the
# panel offers it a slider; moved, the picture is that of the script with
# the value written on its Program line (tests/data/web/unset.glib). The
# press goes 30% along the control: its label is long, and past the
# slider's frame a press does nothing.
echo "  a uniform the script never sets, moved in the panel"
unset_live="$(NODE_PATH=/usr/share/nodejs node tools/page-live-view.mjs "file://$page" tests/data/web/unset.glib \
                - - "$pictures/live" uBright=0.3 2>&1)"
bright="$(python3 -c 'import json, sys; r = json.loads(sys.argv[1]); print(r["sliders"][0]["value"])' "$unset_live" 2>/dev/null)"
sed "s/^Program Forgot uStripes <1. 6. 12.>/& uBright <0. $bright 1.>/" tests/data/web/unset.glib > "$pictures/unset_set.glib"
cp tests/data/web/compat_pattern.vert tests/data/web/unset.frag "$pictures/"
"$g" -q render "$pictures/unset_set.glib" --size 512x512 -o "$pictures/unset_desktop.png"
[ -n "$bright" ] && [ "$bright" != 0 ] && grep -q '"drawn":"0"' <<<"$unset_live" &&
   same_picture "$pictures/live/slider-uBright.png" "$pictures/unset_desktop.png"
tally $? "the panel's control for the unset uBright (at $bright) is not render's picture with it set: $unset_live"

# A browser without EXT_color_buffer_float (some phones'): a script that
# renders into an RGBA16F target gets one error at that texture's line with
# the reason, and nothing is drawn (?no-float-targets leaves it off).
got="$(in_browser "render=scripts/exercises/ex3_separable.glib&no-float-targets")"
want="1
scripts/exercises/ex3_separable.glib:12:1: error: WebGL 2 renders into RGBA16F only with EXT_color_buffer_float, which this browser lacks; make it RGBA8, or use a desktop browser (all have it)
Texture2D 6 512 512 RGBA16F     # after the horizontal pass
^
1 error, 0 warnings"
[ "$got" = "$want" ]
tally $? "a float target without EXT_color_buffer_float must be one error at its line: $got"

# A lesson whose file would leave the page's /user folder is refused as a
# whole, with the reason, and nothing is drawn.
printf '{"files": {"a.glib": "", "../escape.glib": ""}}\n' > "$pictures/hostile.json"
verdict="$(page_dom "file://$page?lesson=file://$pictures/hostile.json" --allow-file-access-from-files |
  grep -o '<p id="verdict"[^<]*')"
grep -q 'data-exit="2"' <<<"$verdict" && grep -Eq 'refused: the path ("|&quot;)\.\./escape\.glib("|&quot;) leaves the folder' <<<"$verdict"
tally $? "a lesson path leaving /user was not refused: $verdict"

# A link from anyone must never run code in the page (issue 30): a lesson is
# JSON data from the page's own origin, never a script. Each payload below
# would mark the body with data-pwned if it ran.
# What the page at URL shows of its lesson, on one line.
lesson_state() {  # URL [CHROMIUM FLAGS]
  page_dom "$@" | python3 -c '
import html, re, sys
dom = sys.stdin.read()
v = re.search(r"<p id=\"verdict\"([^>]*)>([^<]*)", dom)
attrs, text = (v.group(1), html.unescape(v.group(2))) if v else ("", "")
print("ready=%d pwned=%d refused=%d png=%d | %s" % ("data-ready=\"1\"" in dom, "data-pwned" in dom,
      "data-lesson=\"refused\"" in attrs, "data-png=" in dom, text))'
}
urlq() { python3 -c 'import sys, urllib.parse as u; print(u.quote(sys.argv[1], safe=""))' "$1"; }
payload='document.body.dataset.pwned=1;globalThis.glimmerLesson={files:{"a.glib":""}}'
# (a) a data: URL, the script in the link itself.
state="$(lesson_state "file://$page?lesson=$(urlq "data:text/javascript,$payload")" --allow-file-access-from-files)"
[[ "$state" == "ready=1 pwned=0 refused=1 png=0 | refused: the lesson \"data:text/javascript,"*"is not on this disk"* ]]
tally $? "a ?lesson=data: link must be refused and never run: $state"
# (b) a JavaScript file beside the page, as lessons were before: read as
# text, not JSON, refused; never run.
printf '%s;\n' "$payload" > "$pictures/lesson-script.js"
state="$(lesson_state "file://$page?lesson=file://$pictures/lesson-script.js" --allow-file-access-from-files)"
[[ "$state" == "ready=1 pwned=0 refused=1 png=0 | refused: the lesson \""*"lesson-script.js\" is not a lesson: JSON"* ]]
tally $? "a lesson that is a script must not run: $state"
# The same over HTTP (a lesson folder written with --static, served on
# loopback): its own lesson.json draws render's picture; a script from
# another origin (another port) is refused and never fetched; a script of
# its own origin is refused as not a lesson.
python3 tools/web_lesson.py pack "$pictures/lesson" "$web/src/web" --static "$pictures/site" >/dev/null
mkdir "$pictures/elsewhere"
printf '%s;\n' "$payload" | tee "$pictures/elsewhere/evil.js" > "$pictures/site/evil.js"
free_port() { python3 -c 'import socket; s = socket.socket(); s.bind(("127.0.0.1", 0)); print(s.getsockname()[1])'; }
site_port="$(free_port)" other_port="$(free_port)"
python3 -m http.server --bind 127.0.0.1 --directory "$pictures/site" "$site_port" >/dev/null 2>&1 & site_pid=$!
python3 -m http.server --bind 127.0.0.1 --directory "$pictures/elsewhere" "$other_port" >/dev/null 2>&1 & other_pid=$!
trap 'kill "$site_pid" "$other_pid" 2>/dev/null; rm -rf "$profile" "$pictures"' EXIT
for port in "$site_port" "$other_port"; do
  for _ in $(seq 50); do python3 -c "import urllib.request as r; r.urlopen('http://127.0.0.1:$port/')" 2>/dev/null && break; sleep 0.1; done
done
site="http://127.0.0.1:$site_port/index.html"
page_dom "$site" | python3 -c '
import base64, re, sys
m = re.search(r"data-png=\"data:image/png;base64,([^\"]*)\"", sys.stdin.read())
sys.stdout.buffer.write(base64.b64decode(m.group(1)) if m else b"")' > "$pictures/static.png"
echo "  a --static lesson folder, served over HTTP, against render"
[ -s "$pictures/static.png" ] && same_picture "$pictures/static.png" "$pictures/packed_desktop.png"
tally $? "the --static lesson served over HTTP did not draw render's picture"
state="$(lesson_state "$site?lesson=$(urlq "http://127.0.0.1:$other_port/evil.js")")"
[[ "$state" == "ready=1 pwned=0 refused=1 png=0 | refused: the lesson \"http://127.0.0.1:$other_port/evil.js\" is not on this page's own site (http://127.0.0.1:$site_port)"* ]]
tally $? "a lesson on another origin must be refused and never run: $state"
state="$(lesson_state "$site?lesson=evil.js")"
[[ "$state" == "ready=1 pwned=0 refused=1 png=0 | refused: the lesson \"evil.js\" is not a lesson: JSON"* ]]
tally $? "a script of the page's own origin named as a lesson must not run: $state"
kill "$site_pid" "$other_pid" 2>/dev/null

# (c) A packed lesson is data too: a file named '<!--<script>' and text
# holding '</script>' cannot end or stretch its element; the page opens
# from disk and draws.
mkdir "$pictures/tricky"
cp tests/data/web/lit_es.* "$pictures/tricky/"
trick="</script><script>$payload</script><!--<script>"
printf '# %s\n' "$trick" >> "$pictures/tricky/lit_es.glib"
printf '%s\n' "$trick" > "$pictures/tricky/<!--<script>"
python3 tools/web_lesson.py pack "$pictures/tricky" "$web/src/web" --html "$pictures/tricky.html" >/dev/null
page_dom "file://$pictures/tricky.html" > "$pictures/tricky.dom"
python3 -c '
import base64, re, sys
m = re.search(r"data-png=\"data:image/png;base64,([^\"]*)\"", open(sys.argv[1]).read())
sys.stdout.buffer.write(base64.b64decode(m.group(1)) if m else b"")' "$pictures/tricky.dom" > "$pictures/tricky.png"
"$g" -q render "$pictures/tricky/lit_es.glib" --size 512x512 -o "$pictures/tricky_desktop.png"
echo "  a packed lesson with a file named '<!--<script>' holding '</script>', against render"
! grep -q data-pwned "$pictures/tricky.dom" && [ -s "$pictures/tricky.png" ] &&
  same_picture "$pictures/tricky.png" "$pictures/tricky_desktop.png"
tally $? "the packed lesson with '<!--<script>' did not open and draw (or its text ran)"

# (d) The Content-Security-Policy: in the page and the packed page, no
# inline script but by hash, no eval but WebAssembly's, no plugin, no
# <base>; the packed page names no script file and hashes each inline one.
python3 - "$page" "$pictures/tricky.html" <<'EOF'
import base64, hashlib, re, sys
ok = True
for path in sys.argv[1:]:
    text = open(path, encoding="utf-8").read()
    m = re.search(r'<meta http-equiv="Content-Security-Policy" content="([^"]*)">', text)
    policy = {d.split()[0]: d.split()[1:] for d in m.group(1).split(";") if d.split()} if m else {}
    script = policy.get("script-src", [])
    good = ("'wasm-unsafe-eval'" in script and "'unsafe-inline'" not in script and "'unsafe-eval'" not in script
            and not any(s in ("*", "data:", "blob:", "http:", "https:") for s in script)
            and policy.get("object-src") == ["'none'"] and policy.get("base-uri") == ["'none'"])
    if path.endswith("tricky.html"):
        inline = re.findall(r"<script>(.*?)</script>", text, re.S)
        hashes = {"'sha256-" + base64.b64encode(hashlib.sha256(c.encode()).digest()).decode() + "'" for c in inline}
        good = good and "'self'" not in script and len(inline) == 6 and hashes <= set(script) and "<script src=" not in text
    else:
        good = good and "<script>" not in text
    if not good:
        print(f"    {path}: {m.group(0) if m else 'no Content-Security-Policy'}")
        ok = False
sys.exit(0 if ok else 1)
EOF
tally $? "the page or the packed page lacks the Content-Security-Policy"
# ...and the browser keeps to it: an inline script added to the packed
# page (no hash) does not run, and the page still opens and draws.
python3 -c 'import sys; head, tail = open(sys.argv[1]).read().rsplit("</body>", 1)
open(sys.argv[2], "w").write(head + "<script>document.body.dataset.pwned=1</script>\n</body>" + tail)' "$pictures/tricky.html" "$pictures/injected.html"
state="$(lesson_state "file://$pictures/injected.html")"
[[ "$state" == "ready=1 pwned=0 refused=0 png=1 | lit_es.glib: drawn" ]]
tally $? "an inline script without its hash ran in the packed page: $state"

# The packer takes only the lesson's own files (issue 30): a hard link (the
# same file as one outside the folder) and a symbolic link are skipped, said
# on stderr, and their content is nowhere in the lesson it writes.
mkdir -p "$pictures/linked"
echo "secret-outside-$$" > "$pictures/outside.txt"
cp tests/data/web/lit_es.* "$pictures/linked/"
ln "$pictures/outside.txt" "$pictures/linked/hard.txt"
ln -s "$pictures/outside.txt" "$pictures/linked/soft.txt"
said="$(python3 tools/web_lesson.py pack "$pictures/linked" "$web/src/web" --static "$pictures/linked-site" 2>&1 >/dev/null)"
grep -q "skipped .*hard.txt: a hard link" <<<"$said" && grep -q "skipped .*soft.txt: a symbolic link" <<<"$said" &&
  python3 -c 'import base64, json, sys
files = json.load(open(sys.argv[1]))["files"]
sys.exit(0 if "lit_es.glib" in files and not any(b"secret-outside" in base64.b64decode(v) for v in files.values()) else 1)' \
  "$pictures/linked-site/lesson.json"
tally $? "the packer took a hard or symbolic link into the lesson: $said"

# Opened with nothing asked, the page draws the seed bloom (it was blank
# until Draw), and its list holds the lesson's scripts, not the project's
# test scripts (issue 27).
opened="$(page_dom "file://$page" --allow-file-access-from-files | python3 -c '
import re, sys
dom = sys.stdin.read()
verdict = re.search(r"<[^>]*id=\"verdict\"[^>]*>([^<]*)<", dom)
options = re.findall(r"<option value=\"([^\"]*)\"", dom)
print(verdict.group(1) if verdict else "no verdict", "|", len(options), "scripts,",
      sum(o.startswith("/lesson:tests/") for o in options), "test scripts")')"
[[ "$opened" == "scripts/bloom.glib: drawn | "*" scripts, 0 test scripts" ]]
tally $? "the page opened with nothing asked did not draw the seed, or lists test scripts: $opened"

# Stand-ins in the page's live view, as in `glimmer view` (issue 25): a
# script whose image was not handed in opens, drawn, with the warning that
# says a stand-in took its place (7 of 10 such classroom scripts failed).
got="$(in_browser "view=tests/data/web/stand_in.glib")"
[ "$(head -1 <<<"$got")" = 0 ] && grep -q "cannot find texture 'not_handed_in.bmp' .*a stand-in takes its place" <<<"$got"
tally $? "the live view did not open a script with a missing image with a stand-in: $got"

echo "web: $passed passed, $failed failed"
[ "$failed" -eq 0 ]
