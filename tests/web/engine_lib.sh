# Sourced by the engine groups (tests/web/engine_chromium.sh,
# engine_firefox.sh, engine_webkit.sh) after page_lib.sh: the page's checks
# in one browser engine (issue 27), the same in each. tools/page-engine.mjs
# drives the engine (Chromium and Firefox ESR through puppeteer-core from
# tools/node_modules, WebKitGTK through WebKitWebDriver) under a virtual X
# server of the group's own, and this file compares what it saw with the
# desktop:
# - the seed (scripts/bloom.glib) opened in the live view: drawn, no error,
#   its first picture render's (--size 512x512);
# - Save PNG: the page downloads bloom.png, render's picture;
# - the uAdd slider pressed with the mouse: render's picture with --set at
#   the value the slider shows; glimmerPage.set("uAdd=2"): render's with
#   --set uAdd=2;
# - a typo typed into bloom.frag in the editor: one error at 13:52, marked on
#   line 13, the picture and the value kept;
# - the page reloaded: the edit comes back with its error; Revert: gone;
# - the engine's figures (first picture, the heavy seed's redraw) printed on
#   a line "figures: ..." for docs/browser.md's table;
# - engine_packed_lesson: the seed as a one-file lesson opened from disk
#   draws render's picture; engine_from_disk_says: where the engine lets a
#   page opened from disk read nothing beside it, the page says what to do.
# Usage, in a group: engine_checks ENGINE PAGE_URL; engine_packed_lesson
# ENGINE; engine_from_disk_says ENGINE

# What the engine needs, commands or paths: a missing one stops the group
# (a failure, never a skip), naming the install step.
need_engine() {
  local what
  for what in node "$@"; do
    if [[ "$what" == */* ]]; then [ -e "$what" ]; else command -v "$what" >/dev/null; fi ||
      { echo "web $group: $what is missing: run tools/install-deps.sh"; exit 1; }
  done
}

# Runs a command with DISPLAY on an X server of its own (Xvfb picks a free
# display and says which: two groups side by side never race for one, as
# xvfb-run -a may), ended with the command.
with_x() {
  local fifo="$pictures/xdisplay.$RANDOM" display xvfb rc
  mkfifo "$fifo"
  Xvfb -displayfd 3 -screen 0 1600x1200x24 -nolisten tcp 3>"$fifo" >/dev/null 2>&1 &
  xvfb=$!
  read -r -t 20 display <"$fifo"
  rm -f "$fifo"
  if [ -z "$display" ]; then kill "$xvfb" 2>/dev/null; echo "Xvfb did not start" >&2; return 1; fi
  DISPLAY=":$display" "$@"
  rc=$?
  kill "$xvfb" 2>/dev/null
  wait "$xvfb" 2>/dev/null
  return "$rc"
}

engine_checks() {  # ENGINE PAGE_URL
  local engine="$1" url="$2" out="$pictures/$1" got
  mkdir -p "$out"
  echo "  the page's checks in $engine ($url)"
  got="$(with_x timeout 140 node tools/page-engine.mjs "$engine" "$url" "$out" 2>"$out/stderr")"
  engine_json="$(tail -1 <<<"$got")"
  # One field of what the engine saw, by a Python expression over it.
  field() { python3 -c 'import json, sys; r = json.loads(sys.argv[1]); print(eval(sys.argv[2], {"r": r}))' "$engine_json" "$1" 2>/dev/null; }
  # A check over what the engine saw; when it fails, the part named by
  # SHOW (a Python expression, default the whole) and the tool's last words.
  check_engine() {  # DESCRIPTION PYTHON-CONDITION [SHOW]
    python3 -c 'import json, sys; r = json.loads(sys.argv[1]); sys.exit(0 if eval("(" + sys.argv[2] + ")", {"r": r}) else 1)' \
      "$engine_json" "$2" 2>/dev/null
    tally $? "$engine: $1: $(field "${3:-r}" | cut -c1-1200) $(tail -3 "$out/stderr")"
  }
  check_engine "the page must open the seed drawn, with no error and a WebGL 2 context, and say when its first picture came" \
    "'failed' not in r and r['first']['exit'] == 0 and r['first']['errors'] == 0 and r['first']['firstPictureMs'] > 0
     and r['renderer'] != 'no WebGL 2'" "{k: r.get(k) for k in ('failed', 'renderer', 'first')}"
  # Its shaders from the kept translations (web_translations.cpp): none
  # translated, so no glslang before the first picture.
  check_engine "the seed's first picture must take every shader from the kept translations (HITS 0 KEPT)" \
    "int(r['first']['firstTranslations'].split()[0]) > 0 and r['first']['firstTranslations'].split()[1] == '0'" \
    "r['first'].get('firstTranslations')"
  "$g" -q render scripts/bloom.glib --size 512x512 -o "$pictures/seed.png"
  "$g" -q render scripts/bloom.glib --size 512x512 --set uAdd=2 -o "$pictures/add2.png"
  echo "    the first picture against glimmer render"
  [ -s "$out/seed.png" ] && same_picture "$out/seed.png" "$pictures/seed.png"
  tally $? "$engine: the page's first picture of the seed is not render's"
  check_engine "Save PNG must download the picture as bloom.png" "r['saved'] and r['saved']['name'] == 'bloom.png'" "r.get('saved')"
  echo "    Save PNG's picture against glimmer render"
  [ -s "$out/save.png" ] && same_picture "$out/save.png" "$pictures/seed.png"
  tally $? "$engine: the picture Save PNG downloads is not render's"
  local value
  value="$(field 'r["slider"]["value"]')"
  echo "    the uAdd slider pressed at its middle (uAdd=$value) against glimmer render --set"
  "$g" -q render scripts/bloom.glib --size 512x512 --set "uAdd=$value" -o "$pictures/slider.png" 2>/dev/null
  [ -n "$value" ] && [ "$value" != 0 ] && [ -s "$out/slider.png" ] && same_picture "$out/slider.png" "$pictures/slider.png"
  tally $? "$engine: the slider pressed with the mouse did not give render's picture at its value ('$value')"
  check_engine "glimmerPage.set(\"uAdd=2\") must take, and the slider say 2" "r['added']['set'] == 1 and r['added']['value'] == '2'" "r.get('added')"
  echo "    uAdd=2 against glimmer render --set uAdd=2"
  [ -s "$out/add2.png" ] && same_picture "$out/add2.png" "$pictures/add2.png"
  tally $? "$engine: the live edit uAdd=2 is not render's picture with --set uAdd=2"
  local want="shaders/bloom.frag:13:52: error: 'undeclaredTypo': undeclared identifier"
  check_engine "a typo typed at the end of line 13 of bloom.frag must be one error, '$want', marked on line 13, the value kept" \
    "r['clickedAt'] == [13, 50] and r['broken']['exit'] == 1 and r['broken']['errors'] == 1
     and \"$want\" in r['broken']['diagnostics'] and r['broken']['markedLines'] == '13'
     and \"'undeclaredTypo': undeclared identifier\" in r['broken']['message'] and r['broken']['uAdd'] == '2'" \
    "{k: r.get(k) for k in ('failed', 'clickedAt', 'broken')}"
  [ -s "$out/broken.png" ] && [ "$(compare -metric AE "$out/broken.png" "$out/add2.png" null: 2>&1)" = 0 ]
  tally $? "$engine: the broken edit did not keep the last good picture"
  check_engine "the typed edit must come back when the page is reloaded, with its error" \
    "'undeclaredTypo;' in r['reloaded']['file'] and r['reloaded']['errors'] == 1 and r['reloaded']['markedLines'] == '13'
     and r['reloaded']['kept'] == 1 and 'restored your unsaved edits of shaders/bloom.frag' in r['reloaded']['note']" \
    "{k: r.get(k) for k in ('failed', 'reloaded')}"
  check_engine "Revert must bring the file back, the error gone, nothing kept" \
    "'undeclaredTypo' not in r['reverted']['file'] and r['reverted']['exit'] == 0 and r['reverted']['errors'] == 0
     and r['reverted']['kept'] == 0" "{k: r.get(k) for k in ('failed', 'reverted')}"
  check_engine "the figures must be measured (three redraws of the heavy seed)" \
    "len([d for d in r['figures']['redraws'] if d.get('pictureMs', 0) > 0]) == 3" \
    "{k: r.get(k) for k in ('failed', 'figures')}"
  python3 -c '
import json, statistics, sys
r = json.loads(sys.argv[1])
d = [x["pictureMs"] for x in r["figures"]["redraws"]]
print("    figures: %s | %s | first picture %d ms | redraw at uHalfSize 11 %.0f ms (median of %s) | idle frame %s ms"
      % (r["version"], r["renderer"], r["figures"]["firstPictureMs"], statistics.median(d),
         ", ".join("%.0f" % x for x in d), r["figures"]["idleFrameMs"]))' "$engine_json" 2>/dev/null
}

# The seed as a one-file lesson (tools/web_lesson.py pack --html: the page,
# its module and the lesson's files in one HTML file) at DIR/lesson.html,
# packed with GLIMMER from the module in WEB_DIR (tools/first-picture.sh
# uses it too).
pack_seed_lesson() {  # DIR WEB_DIR GLIMMER
  local lesson="$1"
  mkdir -p "$lesson/scripts" "$lesson/shaders" "$lesson/textures"
  cp scripts/bloom.glib "$lesson/scripts/"
  cp shaders/superblur.vert shaders/superblur.frag shaders/bloom.vert shaders/bloom.frag "$lesson/shaders/"
  cp textures/grid.bmp "$lesson/textures/"
  python3 tools/web_lesson.py pack "$lesson/scripts" "$2" --html "$lesson/lesson.html" --glimmer "$3" >/dev/null
}

# The packed seed opened from disk with no setting changed, as a student
# double-clicks it: it opens drawing the seed, render's picture.
engine_packed_lesson() {  # ENGINE
  local engine="$1" out="$pictures/$1-packed" lesson="$pictures/packed-lesson" seen
  mkdir -p "$out"
  pack_seed_lesson "$lesson" "$web/src/web" "$g"
  echo "  the seed as a one-file lesson, opened from disk in $engine"
  seen="$(with_x timeout 60 node tools/page-engine.mjs "$engine" "file://$lesson/lesson.html" "$out" --opening 2>"$out/stderr" | tail -1)"
  python3 -c 'import json, sys; r = json.loads(sys.argv[1]); sys.exit(0 if r["ready"] == "1" and r["verdict"] == "scripts/bloom.glib: drawn" else 1)' \
    "$seen" 2>/dev/null
  tally $? "$engine: the one-file lesson opened from disk must draw scripts/bloom.glib: $(cut -c1-800 <<<"$seen") $(tail -3 "$out/stderr")"
  python3 -c 'import json, sys; t = json.loads(sys.argv[1])["firstTranslations"].split(); sys.exit(0 if int(t[0]) > 0 and t[1] == "0" else 1)' \
    "$seen" 2>/dev/null
  tally $? "$engine: the one-file lesson's first picture must take every shader from its kept translations: $(cut -c1-300 <<<"$seen")"
  [ -s "$pictures/seed.png" ] || "$g" -q render scripts/bloom.glib --size 512x512 -o "$pictures/seed.png"
  [ -s "$out/opening.png" ] && same_picture "$out/opening.png" "$pictures/seed.png"
  tally $? "$engine: the one-file lesson's first picture is not render's"
}

# index.html opened from disk where the engine lets the page read nothing
# beside it (WebKit, as Safari; Chromium without its flag): the page must say
# so, and what to do, on the page, never stay blank.
engine_from_disk_says() {  # ENGINE
  local engine="$1" out="$pictures/$1-disk" seen
  mkdir -p "$out"
  echo "  index.html opened from disk in $engine"
  seen="$(with_x timeout 60 node tools/page-engine.mjs "$engine" "file://$page" "$out" --opening 2>"$out/stderr" | tail -1)"
  python3 -c '
import json, sys
r = json.loads(sys.argv[1])
box = r["cannotStart"] or {}
sys.exit(0 if box.get("shown") and box.get("fromDisk") == "1" and "one-file lesson" in box.get("text", "")
         and "http.server" in box.get("text", "") else 1)' "$seen" 2>/dev/null
  tally $? "$engine: opened from disk, the page must say it cannot load its module there and what to do: $(cut -c1-800 <<<"$seen") $(tail -3 "$out/stderr")"
}
