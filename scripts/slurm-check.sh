#!/usr/bin/env bash
# Checks the Slurm job-array recipe of docs/batch.md on this one machine (not run in CI):
#   1. installs Debian's slurm-wlm and munge if missing (apt-get; needs root),
#   2. starts munged, slurmctld and slurmd on loopback with a minimal slurm.conf in a temp dir,
#   3. synthesises N small subjects and submits a 2-task array running
#      `bodyspace batch --shard $SLURM_ARRAY_TASK_ID/$SLURM_ARRAY_TASK_COUNT`, one OUT per task,
#   4. waits, checks every subject got a fit exactly once, builds a model over both shards,
#   5. stops the daemons it started (by their pid files) and removes the temp dir
#      (KEEP=1 keeps it for a look at the logs).
# Usage: bash scripts/slurm-check.sh [N]   (default N = 4 subjects)
set -euo pipefail
cd "$(dirname "$0")/.."
export PATH="$HOME/.cargo/bin:$PATH"
ROOT=$PWD
N=${1:-4}

need=()
command -v slurmctld > /dev/null || need+=(slurm-wlm)
command -v munged > /dev/null || need+=(munge)
if [ ${#need[@]} -gt 0 ]; then
  echo "slurm-check: installing ${need[*]}"
  apt-get update -qq
  DEBIAN_FRONTEND=noninteractive apt-get install -y -qq "${need[@]}" > /dev/null
fi

cargo build --release --quiet --manifest-path crate/Cargo.toml --bin bodyspace
BIN=$ROOT/crate/target/release/bodyspace

WORK=$(mktemp -d /tmp/bodyspace-slurm.XXXXXX)
mkdir -p "$WORK"/{etc,state,spool,log,run,munge,scans}
chmod 755 "$WORK"
NODE=$(hostname -s)
CONF=$WORK/etc/slurm.conf
export SLURM_CONF=$CONF

stop() {
  for pid in "$WORK/run/slurmd.pid" "$WORK/run/slurmctld.pid" "$WORK/munge/munged.pid"; do
    [ -f "$pid" ] && kill "$(cat "$pid")" 2> /dev/null || true
  done
  if [ "${KEEP:-0}" = 1 ]; then echo "slurm-check: kept $WORK"; else rm -rf "$WORK"; fi
}
trap stop EXIT

# MUNGE with its own key and socket, so nothing system-wide is touched.
dd if=/dev/urandom of="$WORK/munge/munge.key" bs=1024 count=1 status=none
chmod 400 "$WORK/munge/munge.key"
SOCKET=$WORK/munge/munge.socket
munged --force --key-file="$WORK/munge/munge.key" --socket="$SOCKET" \
  --pid-file="$WORK/munge/munged.pid" --log-file="$WORK/munge/munged.log" \
  --seed-file="$WORK/munge/munged.seed"

cat > "$CONF" << EOF
ClusterName=bodyspace-check
SlurmctldHost=$NODE(127.0.0.1)
SlurmctldPort=16817
SlurmdPort=16818
SlurmUser=root
SlurmdUser=root
AuthType=auth/munge
AuthInfo=socket=$SOCKET
CredType=cred/munge
StateSaveLocation=$WORK/state
SlurmdSpoolDir=$WORK/spool
SlurmctldPidFile=$WORK/run/slurmctld.pid
SlurmdPidFile=$WORK/run/slurmd.pid
SlurmctldLogFile=$WORK/log/slurmctld.log
SlurmdLogFile=$WORK/log/slurmd.log
ProctrackType=proctrack/linuxproc
TaskPlugin=task/none
JobAcctGatherType=jobacct_gather/none
AccountingStorageType=accounting_storage/none
SchedulerType=sched/builtin
SelectType=select/cons_tres
SelectTypeParameters=CR_Core
ReturnToService=2
MpiDefault=none
NodeName=$NODE NodeAddr=127.0.0.1 CPUs=$(nproc) State=UNKNOWN
PartitionName=check Nodes=$NODE Default=YES MaxTime=INFINITE State=UP
EOF

slurmctld -f "$CONF"
slurmd -f "$CONF" -N "$NODE"
for _ in $(seq 30); do
  sinfo -h -o %T 2> /dev/null | grep -q idle && break
  sleep 1
done
sinfo -h -o "%P %T %D" || { cat "$WORK"/log/*.log; exit 1; }

echo "slurm-check: synthesising $N subjects"
"$BIN" synth --n "$N" --seed 5 --step 10 --out "$WORK/synth" > /dev/null
cp "$WORK"/synth/scan_*.ply "$WORK"/synth/landmarks_*.lnd "$WORK/scans/"

echo "slurm-check: submitting a 2-task array"
sbatch --wait --array=1-2 --cpus-per-task=1 --output="$WORK/log/task-%a.out" << EOF
#!/bin/bash
"$BIN" batch --scans "$WORK/scans" --out "$WORK/out/shard-\$SLURM_ARRAY_TASK_ID" \
  --shard "\$SLURM_ARRAY_TASK_ID/\$SLURM_ARRAY_TASK_COUNT" --jobs 1 --max-unmatched 0.9
EOF
cat "$WORK"/log/task-*.out

fits=$(ls "$WORK"/out/shard-*/fits/*.ply | wc -l)
unique=$(ls "$WORK"/out/shard-*/fits/*.ply | xargs -n1 basename | sort -u | wc -l)
echo "slurm-check: $fits fits ($unique distinct) for $N subjects"
[ "$fits" = "$N" ] && [ "$unique" = "$N" ] || { echo "slurm-check: FAILED"; exit 1; }
"$BIN" build-model --no-quality --fits "$WORK/out/shard-1/fits,$WORK/out/shard-2/fits" \
  --out "$WORK/model.bsm" > /dev/null
echo "slurm-check: OK (every subject fitted once; model built over both shards)"
