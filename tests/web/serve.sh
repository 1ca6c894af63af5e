#!/usr/bin/env bash
# `glimmer serve` with the real page in Chromium (issue 41): a student opens
# their roster link, types into blur.frag and sees it saved; a fresh
# profile (another machine) opens the link and finds the edit; Hand in shows
# the grade with its feedback link; the teacher's grid shows the student
# graded; the teacher's follow-me moves the student's uAdd slider
# (tools/page-serve.mjs). Then the same student's path in Firefox and
# WebKit, each a student of their own (tools/page-engine.mjs --serve, real
# windows under Xvfb as the engine groups have them): link, typed edit,
# saved, a fresh browser continues it, Hand in, the grade. The lesson is the
# blur exercise of tests/data/grading.
# Usage: tests/web/serve.sh [DESKTOP_GLIMMER] [WEB_BUILD_DIR]
source "$(dirname "$0")/page_lib.sh"
source "$(dirname "$0")/engine_lib.sh"
need_engine Xvfb firefox-esr tools/node_modules/puppeteer-core WebKitWebDriver

lab="$pictures/lab"
mkdir -p "$lab"
cp -r tests/data/grading/blur "$lab/lesson"
cp "$lab/lesson/blur.glib" "$lab/lesson/second.glib"  # a second script for the teacher to push
cp -r tests/data/grading/blur "$lab/solution"
printf 'name\nAda Lovelace\nBea Firefox\nCy WebKit\n' > "$lab/roster.csv"
"$g" serve "$lab/lesson" --solution "$lab/solution/blur.glib" --roster "$lab/roster.csv" --port 0 --host 127.0.0.1 \
  --page "$web/src/web" --state "$lab/state" > "$lab/serve.out" 2>&1 &
servers+=($!)
for _ in $(seq 300); do grep -q "kept in:" "$lab/serve.out" && break; sleep 0.1; done
port="$(sed -n 's/.*(port \([0-9]*\)).*/\1/p' "$lab/serve.out")"
teacher="http://127.0.0.1:$port$(sed -n 's|.*teacher: *http://[^/]*\(/teacher/[0-9a-f]*\).*|\1|p' "$lab/serve.out")"
link() { echo "http://127.0.0.1:$port$(grep "^\"$1\"," "$lab/state/links.csv" | sed -n 's|.*,http://[^/]*\(/join/[0-9a-f]*\)$|\1|p')"; }
student="$(link "Ada Lovelace")"
echo "  a student's link, an edit, another machine, a hand-in; the teacher's grid and follow-me"
seen="$(NODE_PATH=/usr/share/nodejs timeout 400 node tools/page-serve.mjs "$student" "$teacher" blur.frag 2>&1)"
check_seen() {  # DESCRIPTION PYTHON-CONDITION over what the page showed
  python3 -c 'import json, sys; r = json.loads(sys.argv[1]); sys.exit(0 if eval("(" + sys.argv[2] + ")", {}, r) else 1)' \
    "$seen" "$2" 2>/dev/null
  tally $? "$1: $(cut -c1-2000 <<<"$seen")"
}
check_seen "the page names the student" 'who == "Ada Lovelace:"'
check_seen "the lesson's scripts are listed as the lesson's (not yours:)" 'scriptLabels == ["blur.glib", "second.glib"]'
check_seen "an edit is saved to the server" 'saved.startswith("saved (version ")'
check_seen "a fresh profile with the same link continues the edit" 'continued is True'
check_seen "Hand in shows the grade and its feedback link" \
  'grade.startswith("hand-in 1: pass, 100") and feedbackHref == "api/feedback/1"'
check_seen "the teacher's grid shows the student graded" 'card == "hand-in 1: pass, 100" and studentsInGrid == 3'
check_seen "follow-me moves the student's slider" 'float(uAddAfter) == 1.75 and float(uAddBefore) != 1.75'
check_seen "follow-me with script= shows that script" 'pushedScript == "second.glib: drawn"'
for pair in "firefox:Bea Firefox" "webkit:Cy WebKit"; do
  engine="${pair%%:*}" name="${pair#*:}"
  echo "  $name in $engine: a link, a typed edit, a fresh browser, a hand-in"
  mkdir -p "$pictures/$engine"
  seen="$(with_x timeout 300 env GLIMMER_ENGINE_SECONDS=280 node tools/page-engine.mjs "$engine" "$(link "$name")" \
          "$pictures/$engine" --serve 2>"$pictures/$engine/stderr" | tail -1)"
  [ -n "$seen" ] || seen="{\"failed\": \"no output: $(tail -3 "$pictures/$engine/stderr" | tr -d '"\\')\"}"
  check_seen "$engine: the page names the student" "who == '$name:'"
  check_seen "$engine: the typed edit is saved" 'saved.startswith("saved (version ")'
  check_seen "$engine: a fresh browser with the same link continues it" 'continued is True'
  check_seen "$engine: Hand in shows the grade and its feedback link" \
    'grade.startswith("hand-in ") and ": pass, 100" in grade and feedbackHref.startswith("api/feedback/")'
done
finish
