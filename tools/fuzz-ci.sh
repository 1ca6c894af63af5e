#!/usr/bin/env bash
# Builds the libFuzzer targets with clang (-DGLIMMER_FUZZ=ON) and runs each
# for a fixed time on a seed corpus made from the repository's own scripts
# and images. Usage: tools/fuzz-ci.sh [SECONDS_PER_TARGET] (default 20).
# Skips (exit 0) when clang is not installed; exits 1 on any finding.
set -euo pipefail
cd "$(dirname "$0")/.."
secs="${1:-20}"
cxx="$(command -v clang++ || command -v clang++-14 || true)"
cc="$(command -v clang || command -v clang-14 || true)"
if [ -z "$cxx" ] || [ -z "$cc" ]; then
  echo "fuzz-ci: clang not found; fuzzing skipped"
  exit 0
fi
CC="$cc" CXX="$cxx" cmake -S . -B build-fuzz -DCMAKE_BUILD_TYPE=RelWithDebInfo -DGLIMMER_FUZZ=ON -DGLIMMER_TESTS=OFF >/dev/null
targets=(fuzz_script fuzz_shader_text fuzz_glsl_lexer fuzz_image_bmp fuzz_image_pngjpeg fuzz_image_hdr fuzz_image_tex fuzz_grade_record)
cmake --build build-fuzz -j2 --target "${targets[@]}"

corpus=build-fuzz/corpus
rm -rf "$corpus" && mkdir -p "$corpus"/{script,shader_text,bmp,pngjpeg,hdr,tex,grade_record}
n=0  # files of the same name in different folders are all kept
for f in $(find scripts shaders tests/data textures -type f); do
  n=$((n + 1)); base="$n-$(basename "$f")"
  case "${f,,}" in
    *.glib) cp "$f" "$corpus/script/$base" ;;
    *.vert|*.frag|*.geom|*.glsl) cp "$f" "$corpus/shader_text/$base" ;;
    *.bmp) cp "$f" "$corpus/bmp/$base" ;;
    *.png|*.jpg|*.jpeg) cp "$f" "$corpus/pngjpeg/$base" ;;
    *.hdr) cp "$f" "$corpus/hdr/$base" ;;
    *.tex) cp "$f" "$corpus/tex/$base" ;;
  esac
done
# A PNG seed (the repository keeps none): 2x2 RGBA, made with zlib.
python3 - "$corpus/pngjpeg/seed.png" <<'PY' || true
import struct, sys, zlib
def chunk(t, d): return struct.pack(">I", len(d)) + t + d + struct.pack(">I", zlib.crc32(t + d))
raw = b"".join(b"\0" + bytes([255, 0, 0, 255, 0, 255, 0, 128]) for _ in range(2))
png = b"\x89PNG\r\n\x1a\n" + chunk(b"IHDR", struct.pack(">IIBBBBB", 2, 2, 8, 6, 0, 0, 0)) + \
      chunk(b"IDAT", zlib.compress(raw)) + chunk(b"IEND", b"")
open(sys.argv[1], "wb").write(png)
PY
# A grading folder's record and header (src/grade/grade_row.h, grade_merge.h).
cat > "$corpus/grade_record/seed.jsonl" <<'REC'
{"student": "ann", "submission": "class/ann", "script": "class/ann/a.glib", "verdict": "look", "score": 91, "ssim": 0.914, "psnr": "inf", "worst_setting": "uX=1", "by_setting": "defaults 1.000 \u00b7 uX=1 0.914", "notes": "a\tb", "diagnostics": "a.glib:1:1: error: x\n  Ortho\n  ^\n", "seconds": 0.25, "picture": "pictures/ann-1.png", "solution": "pictures/solution-1.png"}
REC
printf 'solution: s.glib\nsetting: defaults\nsetting: uX=1\nthresholds: t\nsandbox: on\nstudent: ann\n' > "$corpus/grade_record/seed.txt"
# Shader seeds the repository's files lack: odd #version lines, a long
# identifier, macros that double.
printf '#version 99999999999999999999 compatibility junk\nvoid main() {}\n' > "$corpus/shader_text/version.frag"
python3 -c 'print("#version 150 // " + "x" * 30000 + "\nvoid main() { gl_" + "a" * 20000 + " = vec4(1.); }")' > "$corpus/shader_text/long.frag"
printf '#define A(x) x x\n#define B A(A(A(A(1))))\n/* #version 330 */\nuniform float B;\nvoid main() { gl_FragColor = vec4(B); }\n' > "$corpus/shader_text/macro.frag"
# Suppress nothing of Glimmer's own: these targets touch no GL driver.
for t in "${targets[@]}"; do
  dir="$corpus/${t#fuzz_image_}"; [ "$t" = fuzz_script ] && dir="$corpus/script"
  [ "$t" = fuzz_grade_record ] && dir="$corpus/grade_record"
  [ "$t" = fuzz_shader_text ] && dir="$corpus/shader_text"
  [ "$t" = fuzz_glsl_lexer ] && dir="$corpus/shader_text"
  mkdir -p "build-fuzz/findings/$t"
  echo "fuzz-ci: $t for ${secs}s ($(ls "$dir" | wc -l) seeds)"
  log="build-fuzz/findings/$t/log"
  if ! build-fuzz/fuzz/"$t" -max_total_time="$secs" -timeout=10 -rss_limit_mb=2560 -max_len=1048576 \
       -artifact_prefix="build-fuzz/findings/$t/" "$dir" >"$log" 2>&1; then
    tail -n 60 "$log"
    echo "fuzz-ci: $t found a problem; the input is in build-fuzz/findings/$t/"
    exit 1
  fi
  grep -E "DONE|^Done" "$log"
done
