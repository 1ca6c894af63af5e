#!/usr/bin/env bash
# Runs each test program whole, its cases in a random order, in the locale
# the caller set (CI: de_DE.UTF-8, a decimal comma). CTest runs each case in
# a process of its own, so it never sees one case leave state behind for
# another (a static, a file, an environment variable); this does. The seed
# is printed so a failing order can be replayed:
#   build/tests/test_X --gtest_shuffle --gtest_random_seed=SEED
# Two programs run at a time (GLIMMER_SHUFFLE_JOBS), the longest first:
# CTest already runs cases of different programs side by side, so they
# share nothing that matters, and one at a time left a core idle for most
# of CI's longest step. Each program's time is printed.
# Usage: tools/shuffled-tests.sh [BUILD_DIR] (default build)
set -uo pipefail
cd "$(dirname "$0")/.."
build="${1:-build}"
seed="${GLIMMER_SHUFFLE_SEED:-$(( ($(date +%s) % 99999) + 1 ))}"
jobs="${GLIMMER_SHUFFLE_JOBS:-2}"
echo "shuffled test programs: seed $seed, LANG=${LANG:-} LC_ALL=${LC_ALL:-}, $jobs at a time"
# The panel tour (test_viewer PanelTour.*) is one case of ~100 s whose steps
# run in their own order whatever the shuffle; CTest ran it already, and CI's
# budget is 75 minutes, so it is left out here.
skip='-PanelTour.*'
out="$(mktemp -d)"
trap 'rm -rf "$out"' EXIT

# One program: its log and a line "passed failed exit seconds" in $out.
run_one() {
  local t="$1" name start rc
  name="$(basename "$t")"
  start=$(date +%s)
  "$t" --gtest_shuffle --gtest_random_seed="$seed" --gtest_filter="$skip" >"$out/$name.log" 2>&1
  rc=$?
  local p f
  p=$(sed -n 's/^\[  PASSED  \] \([0-9]*\) tests\?\..*/\1/p' "$out/$name.log" | head -1)
  f=$(sed -n 's/^\[  FAILED  \] \([0-9]*\) tests\?, listed below:.*/\1/p' "$out/$name.log" | head -1)
  echo "${p:-0} ${f:-0} $rc $(( $(date +%s) - start ))" >"$out/$name.result"
}
export -f run_one
export seed skip out

# The longest first (measured whole on 2 cores), so the two streams end together.
long=(test_cli test_viewer test_render test_glman test_pipeline test_serve test_grade)
programs=()
for n in "${long[@]}"; do [ -x "$build/tests/$n" ] && programs+=("$build/tests/$n"); done
for t in "$build"/tests/test_*; do
  [ -x "$t" ] && [ -f "$t" ] || continue
  [[ " ${long[*]} " == *" $(basename "$t") "* ]] || programs+=("$t")
done
printf '%s\n' "${programs[@]}" | xargs -P "$jobs" -I{} bash -c 'run_one "$1"' _ {}

failed=0 passed=0 bad=0  # cases passed and failed; programs that failed
for t in "${programs[@]}"; do
  name="$(basename "$t")"
  read -r p f rc secs <"$out/$name.result" 2>/dev/null || { p=0 f=0 rc=1 secs=0; }
  passed=$((passed + ${p:-0})); failed=$((failed + ${f:-0}))
  echo "  $name: ${p:-0} passed, ${f:-0} failed (exit $rc, ${secs} s)"
  if [ "$rc" -ne 0 ]; then
    bad=$((bad + 1))
    grep -E '^\[  FAILED  \]|Failure' "$out/$name.log" | head -40
  fi
done
echo "shuffled: $passed passed, $failed failed"
[ "$bad" -eq 0 ]
