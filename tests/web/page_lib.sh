# Sourced by each group of the browser build's checks (tests/web/GROUP.sh,
# one CTest test web.GROUP each; tools/test-web.sh runs them all). It holds
# what the groups share:
# - the setup: the arguments (DESKTOP_GLIMMER WEB_BUILD_DIR, default
#   build/src/app/glimmer and build-web; the module is built already, by
#   tools/build-web.sh or CTest's web.build: a group never builds), the
#   repository root as the working folder, and temporary folders of the
#   group's own (its pictures, and a Chromium profile, so that groups run
#   side by side under ctest -j), removed on exit with any server started;
# - the count: tally, and finish, which prints "web GROUP: N passed,
#   M failed" and fails the group when one check did;
# - reading the page in headless Chromium (SwiftShader's WebGL 2, no GPU
#   needed): page_dom, in_browser, lesson_state, dom_png, page_picture;
# - comparing pictures: same_picture (the bound two rasterizers keep);
# - serving a folder over HTTP on loopback (serve), and urlq.
# A group script: `source "$(dirname "$0")/page_lib.sh"`, its checks, then
# `finish` as its last command.
set -uo pipefail
group="$(basename "$0" .sh)"
cd "$(dirname "${BASH_SOURCE[0]}")/../.."
g="${1:-build/src/app/glimmer}"
web="${2:-build-web}"
for tool in chromium node python3 compare; do
  command -v "$tool" >/dev/null || { echo "web $group: $tool is missing: run tools/install-deps.sh"; exit 1; }
done
[ -x "$g" ] || { echo "web $group: no desktop glimmer at $g"; exit 1; }
[ -f "$web/src/web/index.html" ] && [ -f "$web/src/web/glimmer-web.js" ] ||
  { echo "web $group: no web build in $web (tools/build-web.sh $web; CTest: web.build)"; exit 1; }
page="$(realpath "$web")/src/web/index.html"
profile="$(mktemp -d)" pictures="$(mktemp -d)"
servers=()
trap 'kill ${servers[@]+"${servers[@]}"} 2>/dev/null; rm -rf "$profile" "$pictures"' EXIT
passed=0 failed=0
# Counts one check: STATUS (0 passed) and what differs when it did not.
tally() {
  if [ "$1" -eq 0 ]; then passed=$((passed + 1)); else failed=$((failed + 1)); echo "DIFFERS: $2"; fi
}
# The group's count, its last line (CTest's PASS_REGULAR_EXPRESSION reads
# it); the status is non-zero when a check failed.
finish() {
  echo "web $group: $passed passed, $failed failed"
  [ "$failed" -eq 0 ]
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
# The picture a page's DOM (stdin) holds, as PNG bytes on stdout (nothing
# when it holds none).
dom_png() {
  python3 -c '
import base64, re, sys
m = re.search(r"data-png=\"data:image/png;base64,([^\"]*)\"", sys.stdin.read())
sys.stdout.buffer.write(base64.b64decode(m.group(1)) if m else b"")'
}
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
# The page's picture of a script as a PNG file, through the project's own
# command for it (the script's folder handed to the page as a lesson).
# OUT is removed first: a page that gives no picture must not leave the
# previous case's file to be compared (CI stop 51 compared bloom's 512x512
# render with lit_es's 256x256 page picture). When the page fails, what
# render-web said is printed. A page that gave no result at all (no verdict
# in its DOM) is asked once more: Chromium's virtual time runs ahead while
# the module compiles on a loaded machine, and the dump can come before
# the page has drawn; a page that answered with an error is not asked again.
page_picture() {  # SCRIPT SIZE SETS OUT
  local said try
  for try in 1 2; do
    rm -f "$4"
    said="$(WEB_BUILD="$web" tools/render-web.sh "$1" --size "$2" ${3:+--set "$3"} -o "$4" 2>&1 >/dev/null)" &&
      [ -s "$4" ] && return 0
    echo "    the page's picture (try $try): ${said:-no picture and no message}"
    [[ "$said" == *"the page gave no result"* ]] || return 1
  done
  return 1
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
# Serves DIR over HTTP on loopback and sets served_port once it answers;
# the server ends with the group. The port is the one the server bound (it
# is asked for port 0 and prints it): no port is picked first and bound
# later, where another group running beside this one could take it.
serve() {  # DIR
  local log="$pictures/serve.$RANDOM.log"
  served_port=""
  : >"$log"  # before the server opens it: sed reads it at once
  python3 -u -m http.server --bind 127.0.0.1 --directory "$1" 0 >"$log" 2>&1 & servers+=($!)
  for _ in $(seq 50); do
    served_port="$(sed -n 's/^Serving HTTP on [^ ]* port \([0-9]*\) .*/\1/p' "$log")"
    [ -n "$served_port" ] && python3 -c "import urllib.request as r; r.urlopen('http://127.0.0.1:$served_port/')" 2>/dev/null &&
      break
    sleep 0.1
  done
}
