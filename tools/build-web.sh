#!/usr/bin/env bash
# Builds the browser module with Debian's Emscripten (3.1.6):
#   BUILD_DIR/src/web/{index.html, glimmer-page.js, glimmer-web.js, glimmer-web.wasm}
# Open index.html in a browser (from a web server, or from disk with file
# access allowed). Usage: tools/build-web.sh [BUILD_DIR] (default build-web)
set -euo pipefail
cd "$(dirname "$0")/.."
dir="${1:-build-web}"
# Debian's emcc runs its JavaScript optimiser under node, which finds
# Debian's acorn only through NODE_PATH. EM_CACHE stays unset: Debian's
# cache is prebuilt and read-only.
export NODE_PATH="/usr/share/nodejs${NODE_PATH:+:$NODE_PATH}"
unset EM_CACHE
for tool in emcmake chromium node; do
  command -v "$tool" >/dev/null || { echo "build-web: $tool is missing: run tools/install-deps.sh" >&2; exit 1; }
done
if [ ! -f "$dir/CMakeCache.txt" ]; then
  emcmake cmake -S . -B "$dir" -DCMAKE_BUILD_TYPE=Release
fi
cmake --build "$dir" -j2
