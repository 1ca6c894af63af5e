#!/usr/bin/env bash
# Packs what a run on the lent GPU machine (the `device` tool: an NVIDIA GPU,
# no Debian packages, no network) needs into the ignored folder .gl/:
#   .gl/bin/glimmer, .gl/bin/glimmer-bench   this build's programs
#   .gl/lib/                                 the libraries they link (glibc aside)
#   .gl/debs/*.deb                            glvnd's EGL/GL loaders, unpacked there
#   .gl/env.sh                                source it there: unpacks, sets paths
# Carry ".gl" and run e.g. `. .gl/env.sh && tools/bench-shader-cache.sh .gl/bin/glimmer 5 egl-device`.
# Why glvnd's debs: the NVIDIA driver there ships its EGL vendor library
# but no libEGL loader (see docs/PERFORMANCE.md).
# Usage: tools/gpu-bundle.sh [BUILD_DIR] (default build)
set -euo pipefail
cd "$(dirname "$0")/.."
build="${1:-build}"
# .gl/ref (tools/gpu-check.sh --reference) is kept: it takes minutes to make.
rm -rf .gl/bin .gl/lib .gl/debs .gl/root .gl/env.sh && mkdir -p .gl/bin .gl/lib .gl/debs
cp "$build/src/app/glimmer" .gl/bin/
[ -x "$build/src/bench/glimmer-bench" ] && cp "$build/src/bench/glimmer-bench" .gl/bin/
# The render tests (pixels against the CPU's references, the watch's GPU
# counts against the CPU's), run there with GLIMMER_TEST_BACKENDS=egl-device.
# They find their data by the source folder's path here, which env.sh makes
# there as a link to the carried tree when it can.
[ -x "$build/tests/test_render" ] && cp "$build/tests/test_render" .gl/bin/
strip --strip-debug .gl/bin/*  # the carried tree is limited to 64 MiB
(cd .gl/debs && apt-get download libegl1 libglvnd0 libopengl0 libgl1 libglx0 libgles2 libvulkan1 >/dev/null 2>&1)
# Every shared library the programs link, but glibc's (the machine has its
# own) and the GL loaders (from the debs above).
for b in .gl/bin/*; do ldd "$b"; done | awk '/=>/ {print $3}' | sort -u |
  grep -vE '/(libc|libm|libpthread|libdl|librt|ld-linux[^/]*)\.so|/lib(GL|EGL|GLX|GLdispatch|OpenGL|GLESv2)[.-]' |
  while read -r lib; do cp -L "$lib" .gl/lib/; done
cat > .gl/env.sh <<'ENV'
# Sourced on the GPU machine from the repository root.
here="$(pwd)/.gl"
if [ ! -d "$here/root" ]; then
  for d in "$here"/debs/*.deb; do dpkg -x "$d" "$here/root"; done
fi
export LD_LIBRARY_PATH="$here/root/usr/lib/x86_64-linux-gnu:$here/lib${LD_LIBRARY_PATH:+:$LD_LIBRARY_PATH}"
export __EGL_VENDOR_LIBRARY_FILENAMES=/usr/local/nvidia/share/glvnd/egl_vendor.d/10_nvidia.json
ENV
# The render tests' compiled-in source folder, linked to the tree there.
src="$(pwd)"
printf '[ -e %q ] || { mkdir -p %q 2>/dev/null && ln -s "$(pwd)" %q; } 2>/dev/null\n' "$src" "$(dirname "$src")" "$src" >> .gl/env.sh
du -sh .gl
