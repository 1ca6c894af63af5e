#!/usr/bin/env bash
# Installs what Glimmer needs to build and test on Debian 12, from Debian's
# own packages. Safe to run again: apt-get skips what is there.
#   tools/install-deps.sh          everything: build, render, every test
#   tools/install-deps.sh render   only what building and running glimmer
#                                  needs (the README's first command: a
#                                  newcomer's first picture sooner)
set -euo pipefail
SUDO=""
if [ "$(id -u)" -ne 0 ]; then SUDO="sudo"; fi
packages=(
  cmake g++ make pkg-config          # the build
  libosmesa6-dev                      # OSMesa backend
  libegl-dev libgl-dev                # EGL backend, GL headers
  libegl-mesa0 libgl1-mesa-dri        # Mesa's EGL vendor and llvmpipe, for EGL surfaceless on a CPU
  libglm-dev libstb-dev libfmt-dev libcli11-dev libtinyobjloader-dev libtinyexr-dev libpng-dev
  libwebp-dev                         # render --frames: animated WebP (WebPAnimEncoder/Decoder)
  libzip-dev                          # batch --reference: students' zips, unpacked safely (src/grade/safe_unzip.h)
  nlohmann-json3-dev                  # every JSON written and read: batch's report, grades.jsonl, tradeoff (src/util/json.h)
  fonts-dejavu-core                   # labels of sheets and charts (DejaVu Sans through stb_truetype)
  libglfw3-dev libimgui-dev           # glimmer view: the window and its panel
  glslang-dev glslang-tools           # the translation for WebGL 2: desktop GLSL -> SPIR-V (src/shader/web_translate.h)
  libspirv-cross-c-shared-dev spirv-cross  # and SPIR-V -> GLSL ES 3.00 (its C++ libraries come with the -dev package)
  libcpp-httplib-dev libsqlite3-dev libqrencode-dev  # glimmer serve: HTTP, the class's store, the join QR code (src/serve)
)
test_packages=(
  libgtest-dev xvfb xauth             # tests, the viewer's under a virtual X server
  locales                             # de_DE.UTF-8: tests run under a decimal-comma locale too
  clang-14 libclang-rt-14-dev         # libFuzzer targets and sanitizers (tools/fuzz-ci.sh)
  x11-apps                            # xwd: the viewer test reads the X screen back
  xdotool imagemagick                 # viewer tests drive the window and capture it as a person would
  emscripten chromium                 # the browser build (src/web) and its headless tests (tests/web/)
  firefox-esr                         # the page's checks in Firefox (tests/web/engine_firefox.sh)
  webkit2gtk-driver                   # and in WebKit, Safari's engine: WebKitWebDriver, with WebKitGTK's
                                      # MiniBrowser from libwebkit2gtk-4.1-0, which it depends on (engine_webkit.sh)
  node-ws                             # the page driven over the DevTools protocol (tools/cdp-page.mjs)
  libjs-codemirror                    # the page's code editor (CodeMirror 5, src/web/page/glimmer-editor.js)
  python3-fonttools                   # the page's panel fonts cut to Latin-1 (src/web/CMakeLists.txt)
  dpkg-dev                            # apt-get source: glslang and SPIRV-Cross for the browser build (src/web/third_party.cmake)
)
case "${1:-all}" in
  render) ;;
  all) packages+=("${test_packages[@]}") ;;
  *) echo "usage: tools/install-deps.sh [render|all]" >&2; exit 2 ;;
esac
# Update the package lists only when a package is missing: a second run
# should not touch the network.
if ! dpkg-query -W -f='${Status}\n' "${packages[@]}" 2>/dev/null | grep -qv '^install ok installed$' \
   && [ "$(dpkg-query -W -f='${Status}\n' "${packages[@]}" 2>/dev/null | wc -l)" -eq "${#packages[@]}" ]; then
  have_all=1
fi
# The German locale the tests use (tests/lang/locale_test.cpp, .ci/run):
# generated once, when the locales package is there and it is not.
make_locale() {
  if [ "${1:-all}" = all ] && ! locale -a 2>/dev/null | grep -qi '^de_DE\.utf-\?8$'; then
    $SUDO sed -i 's/^# *\(de_DE.UTF-8 UTF-8\)/\1/' /etc/locale.gen
    grep -q '^de_DE.UTF-8 UTF-8' /etc/locale.gen || echo 'de_DE.UTF-8 UTF-8' | $SUDO tee -a /etc/locale.gen >/dev/null
    $SUDO locale-gen >/dev/null
  fi
}
# The browser build compiles glslang and SPIRV-Cross from Debian's source
# packages (src/web/third_party.cmake): `apt-get source` needs a deb-src
# entry, which Debian's images leave out.
have_deb_src() {
  grep -rqsE '^(Types:.*deb-src|deb-src )' /etc/apt/sources.list /etc/apt/sources.list.d/
}
add_deb_src() {
  if [ "${1:-all}" = all ] && ! have_deb_src; then
    printf '%s\n' 'Types: deb-src' 'URIs: http://deb.debian.org/debian' 'Suites: bookworm bookworm-updates' \
      'Components: main' 'Signed-By: /usr/share/keyrings/debian-archive-keyring.gpg' |
      $SUDO tee /etc/apt/sources.list.d/glimmer-src.sources >/dev/null
    $SUDO apt-get update -qq
  fi
}
# The driver library for the page's checks in Firefox and Chromium
# (tools/page-engine.mjs): puppeteer-core from npm, the exact versions of
# tools/package-lock.json, into tools/node_modules (ignored by git). It never
# downloads a browser (puppeteer-core has no install step; the engines are
# Debian's packages above). Run again only when the lock file changed.
node_tools() {
  [ "${1:-all}" = all ] || return 0
  command -v npm >/dev/null || $SUDO apt-get install -y -qq --no-install-recommends npm >/dev/null
  local here
  here="$(cd "$(dirname "$0")" && pwd)"
  if ! cmp -s "$here/package-lock.json" "$here/node_modules/.installed-lock.json" 2>/dev/null; then
    PUPPETEER_SKIP_DOWNLOAD=1 npm ci --prefix "$here" --ignore-scripts --no-audit --no-fund --loglevel=error >/dev/null
    cp "$here/package-lock.json" "$here/node_modules/.installed-lock.json"
  fi
}
if [ -n "${have_all:-}" ]; then
  make_locale "${1:-all}"
  add_deb_src "${1:-all}"
  node_tools "${1:-all}"
  exit 0
fi
export DEBIAN_FRONTEND=noninteractive
add_deb_src "${1:-all}"
$SUDO apt-get update -qq
$SUDO apt-get install -y -qq --no-install-recommends "${packages[@]}" >/dev/null
make_locale "${1:-all}"
node_tools "${1:-all}"
