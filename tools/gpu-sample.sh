#!/bin/bash
# Samples every running `glimmer` process once a second into LOG: its state,
# kernel wait channel, address space and threads; and once, for a worker
# that has run 6 s or more, its kernel stack (/proc/PID/stack, as root) and
# its user stack (eu-stack, from Debian's elfutils: carry it and its
# libraries to the GPU machine, EU_STACK names it). How issue 36's causes
# were found on the H200: workers spinning in glReadPixels behind a shader
# that never ends, and killed workers in NVIDIA's kernel lock
# (os_acquire_rwlock_write) with the others waiting for it.
# Usage: tools/gpu-sample.sh LOG &   (stop it with kill)
log="${1:?tools/gpu-sample.sh LOG}"
eu="${EU_STACK:-eu-stack}"
declare -A seen
while true; do
  now=$(date +%s.%N)
  for p in $(pgrep -x glimmer); do
    st=$(awk '{print $3}' /proc/$p/stat 2>/dev/null); wc=$(cat /proc/$p/wchan 2>/dev/null)
    mem=$(grep -E '^(VmPeak|VmSize|VmRSS|Threads)' /proc/$p/status 2>/dev/null | tr -s ' \t\n' ' ')
    age=$(ps -o etimes= -p $p 2>/dev/null | tr -d ' ')
    echo "$now $p st=$st wchan=$wc age=$age $mem" >> "$log"
    ppid=$(awk '/PPid/{print $2}' /proc/$p/status 2>/dev/null)
    # A worker (its parent is glimmer too), once.
    if [ "${age:-0}" -ge 6 ] && [ -z "${seen[$p]:-}" ] && pgrep -x glimmer | grep -qx "${ppid:-x}"; then
      seen[$p]=1
      { echo "=== STACK pid $p age $age"
        for t in /proc/$p/task/*; do
          echo "-- task $(basename $t) $(cat $t/comm) st=$(awk '{print $3}' $t/stat) wchan=$(cat $t/wchan)"
          head -12 $t/stack 2>/dev/null
        done
        "$eu" -p $p 2>&1 | head -150; } >> "$log.stacks"
    fi
  done
  sleep 1
done
