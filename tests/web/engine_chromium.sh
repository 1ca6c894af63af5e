#!/usr/bin/env bash
# The page's checks in Chromium (issue 27; tests/web/engine_lib.sh says
# which), through tools/page-engine.mjs as in Firefox and WebKitGTK: Debian's
# chromium, driven with puppeteer-core over the DevTools protocol, ANGLE on
# the X server's OpenGL (Mesa's llvmpipe, what Firefox and WebKitGTK draw
# with here, so the three engines' figures compare), the page opened from
# disk with --allow-file-access-from-files as the other groups open it.
# Usage: tests/web/engine_chromium.sh [DESKTOP_GLIMMER] [WEB_BUILD_DIR]
#        (the module built already; tests/web/page_lib.sh says what is shared)
source "$(dirname "$0")/page_lib.sh"
source "$(dirname "$0")/engine_lib.sh"
need_engine Xvfb tools/node_modules/puppeteer-core
engine_checks chromium "file://$page"
engine_packed_lesson chromium
finish
