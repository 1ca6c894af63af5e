#!/usr/bin/env bash
# Builds the test programs that need no GL context with AddressSanitizer and
# UndefinedBehaviorSanitizer (-DGLIMMER_SANITIZE=ON) and runs them. The GL
# test programs are left to the normal build: under ASan, llvmpipe makes
# them too slow for CI's budget (docs/RELIABILITY.md). Leaks are reported,
# Mesa's suppressed by tools/lsan.supp.
set -euo pipefail
cd "$(dirname "$0")/.."
cmake -S . -B build-asan -DCMAKE_BUILD_TYPE=RelWithDebInfo -DGLIMMER_SANITIZE=ON >/dev/null
tests=(test_lang test_image test_geometry test_plan test_shaderlog test_reference)
cmake --build build-asan -j2 --target "${tests[@]}"
export ASAN_OPTIONS=detect_leaks=1:abort_on_error=0 UBSAN_OPTIONS=print_stacktrace=1:halt_on_error=1
export LSAN_OPTIONS=suppressions="$PWD/tools/lsan.supp"
for t in "${tests[@]}"; do
  echo "sanitize-ci: $t"
  (cd build-asan/tests && ./"$t" --gtest_brief=1)
done
