#!/usr/bin/env bash
# The browser build against the desktop build (issue 20, first step): every
# bundled script checked in headless Chromium (SwiftShader, no GPU needed)
# prints exactly the diagnostics and exit status that the desktop's
# `glimmer check` prints, and a missing script is refused the same way.
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
# What the page shows for ?check=PATH: "EXIT\nDIAGNOSTICS", read from the DOM.
in_browser() {
  timeout 60 chromium --headless=new --no-sandbox --user-data-dir="$profile" --use-angle=swiftshader \
    --enable-unsafe-swiftshader --allow-file-access-from-files --virtual-time-budget=10000 \
    --dump-dom "file://$page?check=$1" 2>/dev/null |
    python3 -c '
import html, re, sys
dom = sys.stdin.read()
exit_ = re.search(r"id=\"verdict\" data-exit=\"(\d+)\"", dom)
diag = re.search(r"<pre id=\"diagnostics\">(.*?)</pre>", dom, re.S)
print(exit_.group(1) if exit_ else "no-result")
sys.stdout.write(html.unescape(diag.group(1)) if diag else "")'
}
# The bundled scripts compile cleanly on the desktop, so its `check` says
# nothing a GL driver alone could say, and the outputs must be equal.
for script in $(find scripts -name '*.glib' | sort) scripts/no_such_script.glib; do
  want="$( { "$g" check "$script" 2>&1 >/dev/null; echo "exit $?" >&3; } 3>&1 )"
  desktop_exit="$(tail -1 <<<"$want" | sed 's/exit //')"
  desktop_diags="$(sed '$d' <<<"$want")"
  got="$(in_browser "$script")"
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
echo "web: $passed passed, $failed failed"
[ "$failed" -eq 0 ]
