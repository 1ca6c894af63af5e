#!/usr/bin/env bash
# Grading on a real Slurm: a one-node cluster made on the spot from Debian's
# packages (slurmctld, slurmd, munge; tools/install-deps.sh does not install
# them: `apt-get install slurmctld slurmd slurm-client munge`), a generated
# class graded by a job array of `glimmer batch --reference --shard I/N`,
# the shards joined by `glimmer batch-merge`, and checked against one local
# `glimmer batch` of the same class: every student exactly once, the same
# grades, the same pictures byte for byte.
#
# Everything lives in a fresh folder (config, state, logs, munge's key and
# socket; other ports than the standard ones), so it touches no system
# cluster, and the daemons it starts are stopped by their pids on exit.
# Runs as root (slurmd must start jobs); prints "slurm-grade: ok" at the end.
# Usage: tools/slurm-grade.sh [GLIMMER] [STUDENTS] [SHARDS] (default build/src/app/glimmer, 24, 4)
set -euo pipefail
cd "$(dirname "$0")/.."
repo=$(pwd)
g=$(realpath "${1:-build/src/app/glimmer}")
students=${2:-24}
shards=${3:-4}
for tool in slurmctld slurmd munged sbatch squeue; do
  command -v "$tool" >/dev/null || { echo "slurm-grade: $tool is missing: apt-get install slurmctld slurmd slurm-client munge" >&2; exit 2; }
done
work=$(mktemp -d /tmp/slurm-grade.XXXXXX)
chmod 755 "$work"
pids=()
stop() {
  # Only what this script started, by pid.
  for f in "$work/slurmd.pid" "$work/slurmctld.pid" "$work/munge/munged.pid"; do
    [ -s "$f" ] && kill "$(cat "$f")" 2>/dev/null || true
  done
  sleep 1
  for f in "$work/slurmd.pid" "$work/slurmctld.pid" "$work/munge/munged.pid"; do
    [ -s "$f" ] && kill -9 "$(cat "$f")" 2>/dev/null || true
  done
  if [ "${KEEP:-0}" = 1 ]; then echo "slurm-grade: kept $work" >&2; else rm -rf "$work"; fi
}
trap stop EXIT

# munge: its own key and socket.
mkdir -p "$work/munge" && chmod 700 "$work/munge"
dd if=/dev/urandom of="$work/munge/munge.key" bs=1024 count=1 status=none
chmod 400 "$work/munge/munge.key"
munged --force --socket="$work/munge/munge.socket" --key-file="$work/munge/munge.key" \
  --pid-file="$work/munge/munged.pid" --log-file="$work/munge/munged.log" --seed-file="$work/munge/munged.seed"

# Slurm: this machine as the controller and the only node, as slurmd -C sees it.
host=$(hostname -s)
node=$(slurmd -C | head -1)
mkdir -p "$work/state" "$work/spool"
cat > "$work/slurm.conf" <<CONF
ClusterName=glimmer
SlurmctldHost=$host(127.0.0.1)
SlurmUser=root
SlurmdUser=root
SlurmctldPort=16817
SlurmdPort=16818
AuthType=auth/munge
AuthInfo=socket=$work/munge/munge.socket
CredType=cred/munge
StateSaveLocation=$work/state
SlurmdSpoolDir=$work/spool
SlurmctldPidFile=$work/slurmctld.pid
SlurmdPidFile=$work/slurmd.pid
SlurmctldLogFile=$work/slurmctld.log
SlurmdLogFile=$work/slurmd.log
ProctrackType=proctrack/linuxproc
TaskPlugin=task/none
JobAcctGatherType=jobacct_gather/none
AccountingStorageType=accounting_storage/none
JobCompType=jobcomp/none
SchedulerType=sched/backfill
SelectType=select/cons_tres
SelectTypeParameters=CR_Core
ReturnToService=2
MpiDefault=none
$node NodeAddr=127.0.0.1 State=UNKNOWN
PartitionName=grade Nodes=$host Default=YES MaxTime=INFINITE State=UP
CONF
export SLURM_CONF="$work/slurm.conf"
slurmctld -i
slurmd
for _ in $(seq 60); do
  sinfo -h -o %T 2>/dev/null | grep -qx idle && break
  sleep 1
done
sinfo -h -o %T | grep -qx idle || { echo "slurm-grade: the node did not come up:" >&2; tail -5 "$work/slurmd.log" "$work/slurmctld.log" >&2; exit 1; }
echo "slurm-grade: one-node cluster up ($node)"

# A class: half right, a sixth each almost right, painted for the defaults, blank, not compiling.
sol=$repo/tests/data/grading/solution
cls=$work/class
for k in $(seq 1 "$students"); do
  d=$cls/student$(printf %03d "$k")
  mkdir -p "$d"
  cp "$sol/st.vert" "$sol/rings.glib" "$sol/rings.frag" "$d/"
  case $((k % 6)) in
    1) sed -i 's/(0.5 + 0.5 \* uTint)/(0.52 + 0.48 * uTint)/' "$d/rings.frag" ;;
    2) sed -i 's/6.2831853 \* uFreq/6.2831853 * 6.0/' "$d/rings.frag" ;;
    3) sed -i 's/gl_FragColor = vec4(mix.*/gl_FragColor = vec4(0.0, 0.0, 0.0, 1.0);/' "$d/rings.frag" ;;
    4) sed -i 's/float r = /float r = = /' "$d/rings.frag" ;;
    *) ;;
  esac
done
mkdir -p "$work/results" "$work/logs"
cat > "$work/grade.sbatch" <<SBATCH
#!/bin/bash
#SBATCH --job-name=grade
#SBATCH --array=0-$((shards - 1))
#SBATCH --cpus-per-task=1
#SBATCH --output=$work/logs/grade-%A_%a.out
set -euo pipefail
shard=\$((SLURM_ARRAY_TASK_ID + 1))/\$SLURM_ARRAY_TASK_COUNT
"$g" batch "$cls" --reference "$sol/rings.glib" -o "$work/results/shard\$SLURM_ARRAY_TASK_ID" \\
    --shard "\$shard" --size 128x128 --timeout 30 --jobs "\$SLURM_CPUS_PER_TASK" --backend osmesa || [ \$? -eq 1 ]
SBATCH
job=$(sbatch --parsable "$work/grade.sbatch")
echo "slurm-grade: job array $job submitted ($shards shards of $students students)"
for _ in $(seq 600); do
  [ -z "$(squeue -h -j "$job" 2>/dev/null)" ] && break
  sleep 1
done
[ -z "$(squeue -h -j "$job")" ] || { echo "slurm-grade: the job array did not finish in 10 minutes" >&2; exit 1; }
for f in "$work"/logs/grade-*.out; do sed 's/^/  /' "$f"; done
merge_dirs=()
for i in $(seq 0 $((shards - 1))); do merge_dirs+=("$work/results/shard$i"); done
"$g" batch-merge "${merge_dirs[@]}" -o "$work/results/all"

# The same class in one local batch: the same grades and the same pictures.
"$g" -q batch "$cls" --reference "$sol/rings.glib" -o "$work/local" --size 128x128 --timeout 30 --jobs 2 \
  --backend osmesa || [ $? -eq 1 ]
nocol() { cut -d, -f1-5,7- "$1"; }  # without the seconds
diff <(nocol "$work/local/grades.csv") <(nocol "$work/results/all/grades.csv") \
  || { echo "slurm-grade: the merged grades differ from one local batch" >&2; exit 1; }
rows=$(($(wc -l < "$work/results/all/grades.csv") - 1))
[ "$rows" -eq "$students" ] || { echo "slurm-grade: $rows rows for $students students" >&2; exit 1; }
[ "$(cut -d, -f1 "$work/results/all/grades.csv" | sort | uniq -d | wc -l)" -eq 0 ] \
  || { echo "slurm-grade: a student appears twice" >&2; exit 1; }
same=0
for p in "$work"/local/pictures/student*.png; do
  name=$(basename "$p")
  found=("$work"/results/shard*/pictures/"$name")
  [ ${#found[@]} -eq 1 ] && [ -f "${found[0]}" ] || { echo "slurm-grade: $name drawn by ${#found[@]} shards" >&2; exit 1; }
  cmp -s "$p" "${found[0]}" || { echo "slurm-grade: $name differs from the local batch's" >&2; exit 1; }
  same=$((same + 1))
done
echo "slurm-grade: $rows students, each exactly once; grades equal to one local batch; $same pictures identical"
echo "slurm-grade: ok"
