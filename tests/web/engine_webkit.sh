#!/usr/bin/env bash
# The page's checks in WebKit (Safari's engine; issue 27;
# tests/web/engine_lib.sh says which): Debian's WebKitGTK MiniBrowser driven
# by its WebKitWebDriver over plain W3C WebDriver (tools/page-engine.mjs),
# under Xvfb, on Mesa's llvmpipe. WebKit, as Safari, lets a page opened from
# disk read no file beside it (the module's .wasm) unless a developer
# setting is changed, so the page is served over loopback HTTP, as a class
# gets it from a server; opened from disk, the page must say so and what to
# do, never stay blank.
# Usage: tests/web/engine_webkit.sh [DESKTOP_GLIMMER] [WEB_BUILD_DIR]
#        (the module built already; tests/web/page_lib.sh says what is shared)
source "$(dirname "$0")/page_lib.sh"
source "$(dirname "$0")/engine_lib.sh"
need_engine Xvfb WebKitWebDriver /usr/lib/x86_64-linux-gnu/webkit2gtk-4.1/MiniBrowser
serve "$web/src/web"
engine_checks webkit "http://127.0.0.1:$served_port/index.html"
engine_packed_lesson webkit
engine_from_disk_says webkit
finish
