#!/usr/bin/env bash
# A sharded sweep on a real Slurm: one node on this machine (Debian's slurm-wlm with munge,
# installed when missing, daemons started here and stopped at the end), a stepped job array of 4
# tasks (--array=0-6:2: ids 0, 2, 4, 6, each shard (ID-MIN)/STEP+1 of 4) running the guide's job
# script, `sweep-merge` (which checks every member is there once), and a byte-for-byte comparison
# with the same sweep run unsharded; then the same array with one task failing (as a lost node
# would), whose merge must be refused naming the missing members. Skips (exit 0, saying why) where Slurm cannot be installed or started:
# not root, or no package registry. Needs target/release/gyro-sim (built when missing).
# Usage: gyro-sim/tests/slurm/sharded_sweep.sh
set -euo pipefail
repo="$(cd "$(dirname "$0")/../../.." && pwd)"
skip() { echo "slurm test skipped: $*"; exit 0; }

[ "$(id -u)" -eq 0 ] || skip "starting slurmctld, slurmd and munged here needs root"
if ! command -v slurmctld >/dev/null || ! command -v munged >/dev/null; then
  { apt-get update -qq && DEBIAN_FRONTEND=noninteractive apt-get install -y -qq slurm-wlm munge >/dev/null; } \
    || skip "slurm-wlm could not be installed (apt-get install slurm-wlm)"
fi
[ -x "$repo/target/release/gyro-sim" ] || (cd "$repo" && cargo build --release -q -p gyro-sim)

work="$(mktemp -d /tmp/gyro-slurm.XXXXXX)"
host="$(hostname)"
mkdir -p "$work/state" "$work/spool" /run/munge
chown munge:munge /run/munge 2>/dev/null || true
cat >"$work/slurm.conf" <<CONF
ClusterName=gyrosim
SlurmctldHost=$host
SlurmUser=root
SlurmdUser=root
AuthType=auth/munge
ProctrackType=proctrack/linuxproc
TaskPlugin=task/none
SelectType=select/cons_tres
SelectTypeParameters=CR_Core
StateSaveLocation=$work/state
SlurmdSpoolDir=$work/spool
SlurmctldPidFile=$work/slurmctld.pid
SlurmdPidFile=$work/slurmd.pid
SlurmctldLogFile=$work/slurmctld.log
SlurmdLogFile=$work/slurmd.log
ReturnToService=2
MpiDefault=none
JobAcctGatherType=jobacct_gather/none
AccountingStorageType=accounting_storage/none
NodeName=$host CPUs=$(nproc) State=UNKNOWN
PartitionName=local Nodes=$host Default=YES MaxTime=INFINITE State=UP
CONF
export SLURM_CONF="$work/slurm.conf"
passed=""
stop() {
  pkill -f "$work/" 2>/dev/null || true
  for _ in $(seq 20); do pgrep -f "$work/" >/dev/null || break; sleep 0.25; done
  if [ -n "$passed" ]; then rm -rf "$work"; else echo "slurm test: logs kept in $work"; fi
}
trap stop EXIT
munged --force --socket="$work/munge.socket" --pid-file="$work/munged.pid" --log-file="$work/munged.log" \
  --seed-file="$work/munged.seed" 2>/dev/null || skip "munged did not start"
cat >>"$work/slurm.conf" <<CONF
AuthInfo=socket=$work/munge.socket
CONF
slurmctld -f "$SLURM_CONF" || skip "slurmctld did not start (see $work/slurmctld.log)"
slurmd -f "$SLURM_CONF" || skip "slurmd did not start (see $work/slurmd.log)"
for _ in $(seq 60); do
  [ "$(sinfo -h -o %T 2>/dev/null)" = idle ] && break
  sleep 0.5
done
[ "$(sinfo -h -o %T 2>/dev/null)" = idle ] || skip "the node did not come up: $(sinfo 2>&1 | tail -1)"

sweep=(gyro-sim/scenes/paper/trial3.toml --vary "U3=50:150 rad/s" --vary "Z=0:20" --samples 200 --seed 7)
cd "$repo"
target/release/gyro-sim sweep "${sweep[@]}" --out "$work/whole" >/dev/null
# The guide's job script (docs/sweeps.md), with 4 array tasks on stepped ids, as array NAME whose task LOST fails.
job() {
  cat >"$work/$1.sh" <<JOB
#!/bin/bash
#SBATCH --array=0-6:2
#SBATCH --cpus-per-task=1
#SBATCH --output=$work/$1-%a.log
[ "\$SLURM_ARRAY_TASK_ID" = "$2" ] && exit 1
target/release/gyro-sim sweep ${sweep[*]@Q} --out $work/$1/shard-\$SLURM_ARRAY_TASK_ID
JOB
  sbatch --wait --chdir="$repo" "$work/$1.sh" >/dev/null
}
job lhs "" || { cat "$work"/lhs-*.log; exit 1; }
target/release/gyro-sim sweep-merge --out "$work/lhs" "$work"/lhs/shard-* >/dev/null
cmp "$work/whole/sweep.csv" "$work/lhs/sweep.csv"
rows=$(($(wc -l <"$work/lhs/sweep.csv") - 1))
echo "slurm: 4 array tasks (ids 0-6:2), $rows members merged, equal byte for byte to the unsharded sweep"
# The same array with task 4 lost (as on a failed node): its merge is refused, naming the members missing.
job lost 4 && { echo "slurm: the lost task did not fail"; exit 1; }
if target/release/gyro-sim sweep-merge --out "$work/lost" "$work"/lost/shard-* >"$work/lost.out" 2>&1; then
  echo "slurm: a merge without task 4's shard was accepted:"; cat "$work/lost.out"; exit 1
fi
{ grep -q "members [0-9]" "$work/lost.out" && grep -q "is missing" "$work/lost.out"; } || { echo "slurm: the refusal does not name the missing members:"; cat "$work/lost.out"; exit 1; }
echo "slurm: the array with task 4 lost is refused: $(grep -m1 missing "$work/lost.out")"
passed=1
