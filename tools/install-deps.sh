#!/usr/bin/env bash
# Installs what Glimmer needs to build and test on Debian 12, from Debian's
# own packages. Safe to run again: apt-get skips what is there.
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
  fonts-dejavu-core                   # labels of sheets and charts (DejaVu Sans through stb_truetype)
  libglfw3-dev libimgui-dev           # glimmer view: the window and its panel
  libgtest-dev xvfb xauth             # tests, the viewer's under a virtual X server
  clang-14 libclang-rt-14-dev         # libFuzzer targets and sanitizers (tools/fuzz-ci.sh)
  x11-apps                            # xwd: the viewer test reads the X screen back
  xdotool imagemagick                 # viewer tests drive the window and capture it as a person would
  fonts-dejavu-core                   # glimmer view's panel font (a TTF, crisp at any --ui-scale)
)
# Update the package lists only when a package is missing: a second run
# should not touch the network.
if ! dpkg-query -W -f='${Status}\n' "${packages[@]}" 2>/dev/null | grep -qv '^install ok installed$' \
   && [ "$(dpkg-query -W -f='${Status}\n' "${packages[@]}" 2>/dev/null | wc -l)" -eq "${#packages[@]}" ]; then
  exit 0
fi
export DEBIAN_FRONTEND=noninteractive
$SUDO apt-get update -qq
$SUDO apt-get install -y -qq --no-install-recommends "${packages[@]}" >/dev/null
