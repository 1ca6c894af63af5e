#!/usr/bin/env bash
# The browser build against the desktop build (issue 20), in headless
# Chromium: every bundled script checked in the page prints exactly the
# diagnostics and exit status that the desktop's `glimmer check --web`
# prints (shaders translated for WebGL 2 in both), and a missing script is
# refused the same way.
# Usage: tests/web/check_matches_desktop.sh [DESKTOP_GLIMMER] [WEB_BUILD_DIR]
#        (the module built already; tests/web/page_lib.sh says what is shared)
source "$(dirname "$0")/page_lib.sh"

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

finish
