#!/usr/bin/env bash
# What turning off the driver's on-disk shader cache costs (issue 18,
# backends/driver_shader_cache.h): the "compile" figure of `render --timings`
# (upload, compile and link of every program) for a few scripts, three ways
# in the same run:
#   off   the driver's disk cache off (Mesa's and NVIDIA's): every shader
#         compiled; Glimmer's default under Mesa
#   cold  the driver's cache on (GLIMMER_DRIVER_SHADER_CACHE=1), empty folder
#   warm  the same folder again: shaders come from the cache; Glimmer's
#         default under NVIDIA once a script has run (its cache keeps logs)
# It also counts the driver warnings each way prints, to show what a warm
# cache hides. Prints a table; medians of RUNS runs.
# Usage: tools/bench-shader-cache.sh [GLIMMER] [RUNS] [BACKEND]
#        (default build/src/app/glimmer, 5, auto)
set -euo pipefail
export LC_ALL=C  # the figures are read back as numbers with a decimal point
cd "$(dirname "$0")/.."
g="${1:-build/src/app/glimmer}"
runs="${2:-5}"
backend="${3:-auto}"
work="$(mktemp -d)"
trap 'rm -rf "$work"' EXIT
scripts=(scripts/bloom.glib scripts/bloom/kawase.glib scripts/bloom/learnopengl.glib tests/data/glman/teapot.glib
         tests/data/nvidia/subdivide.glib tests/data/glman/all_commands.glib)

# One render at 64x64; prints "COMPILE_MS WARNINGS" (the warnings that
# come from a driver's compile log: those with a shader file's name).
one() {
  local err
  err="$("$g" render "$1" --size 64x64 --backend "$backend" --timings -o "$work/out.png" 2>&1 >/dev/null || true)"
  local ms
  ms="$(sed -n 's/.* compile \([0-9.]*\) ms.*/\1/p' <<<"$err" | head -1)"
  local warns
  warns="$(grep -cE '\.(vert|frag|geom|tesc|tese|glsl):[0-9]+:[0-9]+: warning:' <<<"$err" || true)"
  echo "${ms:-nan} $warns"
}

# The same with every driver's cache off.
uncached() {
  (
    export GLIMMER_DRIVER_SHADER_CACHE=1 MESA_SHADER_CACHE_DISABLE=true __GL_SHADER_DISK_CACHE=0
    one "$1"
  )
}

# The same with the driver's cache on, in folder $1 (Mesa's and NVIDIA's).
cached() {
  (
    unset MESA_SHADER_CACHE_DISABLE MESA_GLSL_CACHE_DISABLE __GL_SHADER_DISK_CACHE
    export GLIMMER_DRIVER_SHADER_CACHE=1 MESA_SHADER_CACHE_DIR="$1" __GL_SHADER_DISK_CACHE_PATH="$1"
    one "$2"
  )
}

echo "device: $(GLIMMER_DRIVER_SHADER_CACHE=0 "$g" render scripts/bloom.glib --size 8x8 --backend "$backend" --timings -o "$work/out.png" 2>&1 | sed -n 's/: start-up.*//p' | head -1)"
printf '%-40s %10s %10s %10s   %s\n' script "off ms" "cold ms" "warm ms" "warnings off/cold/warm"
for s in "${scripts[@]}"; do
  offs=(); colds=(); warms=(); wo=0; wc=0; ww=0
  for r in $(seq "$runs"); do
    read -r ms w < <(uncached "$s"); offs+=("$ms"); wo=$w
    cache="$work/cache_$r"; mkdir -p "$cache"
    read -r ms w < <(cached "$cache" "$s"); colds+=("$ms"); wc=$w
    read -r ms w < <(cached "$cache" "$s"); warms+=("$ms"); ww=$w
  done
  med() { printf '%s\n' "$@" | sort -g | awk '{a[NR]=$1} END {print a[int((NR+1)/2)]}'; }
  printf '%-40s %10s %10s %10s   %s/%s/%s\n' "$s" "$(med "${offs[@]}")" "$(med "${colds[@]}")" "$(med "${warms[@]}")" "$wo" "$wc" "$ww"
done
