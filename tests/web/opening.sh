#!/usr/bin/env bash
# The page as it opens: with nothing asked it draws the seed bloom and
# lists the lesson's scripts; a script whose image was not handed in opens
# in the live view with a stand-in and the warning saying so.
# Usage: tests/web/opening.sh [DESKTOP_GLIMMER] [WEB_BUILD_DIR]
#        (the module built already; tests/web/page_lib.sh says what is shared)
source "$(dirname "$0")/page_lib.sh"

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

finish
