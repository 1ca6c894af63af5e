#!/usr/bin/env bash
# A lesson is data from the page's own origin, never run (issue 30): a
# data: link, a script, a lesson on another origin, a script of the page's
# own origin, a packed lesson holding '<!--<script>' and '</script>'; the
# page and the packed page keep a Content-Security-Policy, and the browser
# keeps to it; the packer takes no link out of the lesson's folder.
# Usage: tests/web/lesson_security.sh [DESKTOP_GLIMMER] [WEB_BUILD_DIR]
#        (the module built already; tests/web/page_lib.sh says what is shared)
source "$(dirname "$0")/page_lib.sh"

# A link from anyone must never run code in the page (issue 30): a lesson is
# JSON data from the page's own origin, never a script. Each payload below
# would mark the body with data-pwned if it ran.
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
# loopback; that it draws render's picture is tests/web/lessons.sh's): a
# script from another origin (another port) is refused and never fetched;
# a script of its own origin is refused as not a lesson.
mkdir "$pictures/lesson"
cp tests/data/web/lit_es.* "$pictures/lesson/"
python3 tools/web_lesson.py pack "$pictures/lesson" "$web/src/web" --static "$pictures/site" --glimmer "$g" >/dev/null
mkdir "$pictures/elsewhere"
printf '%s;\n' "$payload" | tee "$pictures/elsewhere/evil.js" > "$pictures/site/evil.js"
serve "$pictures/site"; site_port="$served_port"
serve "$pictures/elsewhere"; other_port="$served_port"
site="http://127.0.0.1:$site_port/index.html"
state="$(lesson_state "$site?lesson=$(urlq "http://127.0.0.1:$other_port/evil.js")")"
[[ "$state" == "ready=1 pwned=0 refused=1 png=0 | refused: the lesson \"http://127.0.0.1:$other_port/evil.js\" is not on this page's own site (http://127.0.0.1:$site_port)"* ]]
tally $? "a lesson on another origin must be refused and never run: $state"
state="$(lesson_state "$site?lesson=evil.js")"
[[ "$state" == "ready=1 pwned=0 refused=1 png=0 | refused: the lesson \"evil.js\" is not a lesson: JSON"* ]]
tally $? "a script of the page's own origin named as a lesson must not run: $state"

# (c) A packed lesson is data too: a file named '<!--<script>' and text
# holding '</script>' cannot end or stretch its element; the page opens
# from disk and draws.
mkdir "$pictures/tricky"
cp tests/data/web/lit_es.* "$pictures/tricky/"
trick="</script><script>$payload</script><!--<script>"
printf '# %s\n' "$trick" >> "$pictures/tricky/lit_es.glib"
printf '%s\n' "$trick" > "$pictures/tricky/<!--<script>"
python3 tools/web_lesson.py pack "$pictures/tricky" "$web/src/web" --html "$pictures/tricky.html" --glimmer "$g" >/dev/null
page_dom "file://$pictures/tricky.html" > "$pictures/tricky.dom"
dom_png < "$pictures/tricky.dom" > "$pictures/tricky.png"
"$g" -q render "$pictures/tricky/lit_es.glib" --size 512x512 -o "$pictures/tricky_desktop.png"
echo "  a packed lesson with a file named '<!--<script>' holding '</script>', against render"
! grep -q data-pwned "$pictures/tricky.dom" && [ -s "$pictures/tricky.png" ] &&
  same_picture "$pictures/tricky.png" "$pictures/tricky_desktop.png"
tally $? "the packed lesson with '<!--<script>' did not open and draw (or its text ran)"

# (d) The Content-Security-Policy: in the page and the packed page, no
# inline script but by hash, no eval but WebAssembly's, no plugin, no
# <base>; the packed page names no script file and hashes each inline one.
python3 - "$page" "$pictures/tricky.html" <<'PY'
import base64, hashlib, re, sys
ok = True
# The packed page inlines every script the page names (a new one of the page's is one more).
page_scripts = len(re.findall(r'<script src="[^"]*"></script>', open(sys.argv[1], encoding="utf-8").read()))
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
        good = good and "'self'" not in script and len(inline) == page_scripts and hashes <= set(script) and "<script src=" not in text
    else:
        good = good and "<script>" not in text
    if not good:
        print(f"    {path}: {m.group(0) if m else 'no Content-Security-Policy'}")
        ok = False
sys.exit(0 if ok else 1)
PY
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
said="$(python3 tools/web_lesson.py pack "$pictures/linked" "$web/src/web" --static "$pictures/linked-site" --glimmer "$g" 2>&1 >/dev/null)"
grep -q "skipped .*hard.txt: a hard link" <<<"$said" && grep -q "skipped .*soft.txt: a symbolic link" <<<"$said" &&
  python3 -c 'import base64, json, sys
files = json.load(open(sys.argv[1]))["files"]
sys.exit(0 if "lit_es.glib" in files and not any(b"secret-outside" in base64.b64decode(v) for v in files.values()) else 1)' \
  "$pictures/linked-site/lesson.json"
tally $? "the packer took a hard or symbolic link into the lesson: $said"

# A packed lesson's data is gzip, which the page inflates (issue 27): a
# block made to inflate past what a lesson may hold (100 MB of blanks in
# 100 KB) is refused while it inflates, said on the page, never unpacked
# whole.
python3 - "$pictures/tricky.html" "$pictures/bomb.html" <<'PY'
import base64, gzip, re, sys
page = open(sys.argv[1]).read()
bomb = base64.b64encode(gzip.compress(b'{"files": {"a.glib": "' + b" " * (100 << 20) + b'"}}', 9)).decode()
page = re.sub(r'(<script type="application/gzip" id="glimmer-lesson">)[^<]*', lambda m: m.group(1) + bomb, page, count=1)
open(sys.argv[2], "w").write(page)
PY
state="$(lesson_state "file://$pictures/bomb.html")"
[[ "$state" == "ready=1 pwned=0 refused=1 png=0 | refused: the packed lesson is larger than a lesson may be" ]]
tally $? "a packed lesson inflating past the bound was not refused: $state"

finish
