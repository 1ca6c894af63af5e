#!/usr/bin/env bash
# The page's checks in Firefox (Gecko; issue 27; tests/web/engine_lib.sh
# says which): Debian's firefox-esr, driven with puppeteer-core over
# WebDriver BiDi (tools/page-engine.mjs), a real window under Xvfb (headless
# Firefox has no WebGL 2 here), on Mesa's llvmpipe. The page is opened from
# disk as a student double-clicks it: Firefox reads the module beside it
# with no setting changed. The typo is typed after a click in the editor,
# as a person types it: Firefox's window under Xvfb is never the active
# one, and a focus() alone leaves the editor dropping every key.
# Usage: tests/web/engine_firefox.sh [DESKTOP_GLIMMER] [WEB_BUILD_DIR]
#        (the module built already; tests/web/page_lib.sh says what is shared)
source "$(dirname "$0")/page_lib.sh"
source "$(dirname "$0")/engine_lib.sh"
need_engine Xvfb firefox-esr tools/node_modules/puppeteer-core
engine_checks firefox "file://$page"
engine_packed_lesson firefox
finish
