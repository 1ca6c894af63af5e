#!/usr/bin/env bash
# Renders a script through the browser page, headless, to a PNG: the page's
# counterpart of `glimmer render`, so any script can be compared web against
# desktop (tests/web/pictures.sh uses it).
#   tools/render-web.sh SCRIPT -o OUT.png [--size WxH] [--set NAME=VALUE]...
#   tools/render-web.sh SCRIPT --frames N [--size WxH] [--set ...]
#       instead of a PNG, the page's figures in real time as JSON (time to
#       the first picture, mean ms of N more frames; tools/page-figures.mjs)
# The script's folder goes to the page as a lesson (?lesson=; see
# tools/web_lesson.py for what it holds). The page draws it with WebGL 2 in
# Chromium's SwiftShader; its diagnostics go to stderr as render prints
# them; the exit status is render's (0 drawn, 1 script errors, 2 usage).
# WEB_BUILD (default build-web) is the web build, made when missing.
set -uo pipefail
here="$(cd "$(dirname "$0")/.." && pwd)"
usage() { echo "usage: tools/render-web.sh SCRIPT -o OUT.png [--size WxH] [--set NAME=VALUE]..." >&2; exit 2; }
script="" out="" size="512x512" sets="" frames=""
while [ $# -gt 0 ]; do
  case "$1" in
    -o) out="${2:-}"; shift 2 || usage ;;
    --size) size="${2:-}"; shift 2 || usage ;;
    --set) sets="${sets:+$sets;}${2:-}"; shift 2 || usage ;;
    --frames) frames="${2:-}"; shift 2 || usage ;;
    -*) usage ;;
    *) [ -z "$script" ] || usage; script="$1"; shift ;;
  esac
done
[ -n "$script" ] && { [ -n "$out" ] || [ -n "$frames" ]; } || usage
[ -z "$frames" ] || [[ "$frames" =~ ^[1-9][0-9]{0,4}$ ]] || { echo "render-web: --frames takes 1 to 99999" >&2; exit 2; }
[[ "$size" =~ ^[0-9]+x[0-9]+$ ]] || { echo "render-web: --size takes WxH, not '$size'" >&2; exit 2; }
[ -f "$script" ] || { echo "render-web: $script: no such file" >&2; exit 2; }
web="${WEB_BUILD:-$here/build-web}"
[ -f "$web/src/web/glimmer-web.js" ] || (cd "$here" && tools/build-web.sh "$web" >/dev/null) ||
  { echo "render-web: the web build failed (tools/build-web.sh $web)" >&2; exit 1; }
work="$(mktemp -d)"
trap 'rm -rf "$work"' EXIT
# The lesson (tools/web_lesson.py): the files the script can reach, as JSON
# data the page reads from disk (file: from a file: page); prints the
# script's path inside it.
inner="$(python3 "$here/tools/web_lesson.py" for-script "$script" "$work/lesson.json")" || exit 2
page="$(realpath "$web")/src/web/index.html"
# Query values are URL-encoded (a --set value may hold '&' or '=').
url="$(python3 -c 'import pathlib, sys, urllib.parse as u; print(pathlib.Path(sys.argv[1]).as_uri() + "?" + u.urlencode({"lesson": pathlib.Path(sys.argv[2]).as_uri(), "render": sys.argv[3], "size": sys.argv[4], "set": sys.argv[5], "frames": sys.argv[6]}))' \
  "$page" "$work/lesson.json" "$inner" "$size" "$sets" "${frames:-0}")"
if [ -n "$frames" ]; then
  NODE_PATH=/usr/share/nodejs node "$here/tools/page-figures.mjs" "$url"
  exit
fi
# Virtual time: the page's timers run ahead while it waits, so a budget
# costs only the time the page really works. 30 s was too little for a
# script with a 1.1 MB model, or any under load (issue 39: "the page gave no
# result"); 120 s costs a quick script nothing (4.9 s either way, measured).
# RENDER_WEB_BUDGET_MS changes it; the wall-clock limit follows.
budget="${RENDER_WEB_BUDGET_MS:-120000}"
[[ "$budget" =~ ^[1-9][0-9]{0,6}$ ]] || { echo "render-web: RENDER_WEB_BUDGET_MS takes 1 to 9999999, not '$budget'" >&2; exit 2; }
timeout $((budget / 1000 + 60)) chromium --headless=new --no-sandbox --user-data-dir="$work/profile" --use-angle=swiftshader \
  --enable-unsafe-swiftshader --allow-file-access-from-files --virtual-time-budget="$budget" \
  --dump-dom "$url" 2>/dev/null > "$work/dom.html"
python3 - "$work/dom.html" "$out" <<'EOF'
import base64, html, re, sys
dom = open(sys.argv[1], encoding="utf-8", errors="replace").read()
exit_ = re.search(r'id="verdict"[^>]*data-exit="(\d+)"', dom) or re.search(r'data-exit="(\d+)"[^>]*id="verdict"', dom)
diag = re.search(r'<pre id="diagnostics">(.*?)</pre>', dom, re.S)
if diag:
    # The page marks each file:line:col as a link (<span class="jump">):
    # the text, as glimmer render prints it, without the page's markup.
    sys.stderr.write(html.unescape(re.sub(r"<[^>]*>", "", diag.group(1))))
if not exit_:
    sys.stderr.write("render-web: the page gave no result (did the module load? a heavy script may need more "
                     "than RENDER_WEB_BUDGET_MS of the page's time)\n")
    sys.exit(1)
png = re.search(r'data-png="data:image/png;base64,([^"]*)"', dom)
if exit_.group(1) == "0" and png:
    with open(sys.argv[2], "wb") as f:
        f.write(base64.b64decode(png.group(1)))
    print(f"wrote {sys.argv[2]}")
sys.exit(int(exit_.group(1)))
EOF
