#!/usr/bin/env bash
# A sweep through a real Slurm: a private single-node cluster (slurmctld + slurmd on this host,
# its own slurm.conf, state and ports under WORKDIR) runs hexplore_experiment --emit-slurm's job
# array (two planners, one seed, a short lockstep mission each), and --gather must write the
# comparison of both runs. Skipped (exit 77) without Slurm and munge (Debian: slurm-wlm) or
# without root (slurmd launches the jobs).
#   run_slurm_sweep.sh EXPERIMENT TEAM_FILE WORKDIR
set -euo pipefail
experiment=$1 team=$2 work=$3

for tool in sbatch squeue sinfo slurmctld slurmd munged munge; do
  command -v "$tool" > /dev/null || { echo "SKIP: no $tool (apt-get install slurm-wlm)"; exit 77; }
done
[ "$(id -u)" = 0 ] || { echo "SKIP: slurmd needs root"; exit 77; }

fail() {
  echo "SLURM SWEEP FAIL: $*" >&2
  tail -n 20 "$work/slurm/slurmctld.log" "$work/slurm/slurmd.log" "$work"/sweep/logs/*.log >&2 2>/dev/null || true
  exit 1
}

rm -rf "$work"
mkdir -p "$work/slurm/state" "$work/slurm/spool"
# munge authenticates Slurm's messages; start it unless one already answers.
if ! munge -n 2>/dev/null | unmunge > /dev/null 2>&1; then
  [ -r /etc/munge/munge.key ] || fail "no /etc/munge/munge.key (the munge package makes it)"
  mkdir -p /run/munge && chown munge:munge /run/munge
  su -s /bin/sh munge -c /usr/sbin/munged || fail "munged did not start"
fi

read -r ctld_port slurmd_port < <(python3 -c '
import socket
ports = []
for _ in range(2):
    s = socket.socket(); s.bind(("127.0.0.1", 0)); ports.append(s.getsockname()[1]); s.close()
print(*ports)')
host=$(hostname)
export SLURM_CONF=$work/slurm/slurm.conf
cat > "$SLURM_CONF" <<CONF
ClusterName=hexplore-test
SlurmctldHost=$host
SlurmctldPort=$ctld_port
SlurmdPort=$slurmd_port
AuthType=auth/munge
SlurmUser=root
StateSaveLocation=$work/slurm/state
SlurmdSpoolDir=$work/slurm/spool
SlurmctldPidFile=$work/slurm/slurmctld.pid
SlurmdPidFile=$work/slurm/slurmd.pid
SlurmctldLogFile=$work/slurm/slurmctld.log
SlurmdLogFile=$work/slurm/slurmd.log
ProctrackType=proctrack/linuxproc
TaskPlugin=task/none
SchedulerType=sched/builtin
SelectType=select/cons_tres
SelectTypeParameters=CR_Core
ReturnToService=2
MpiDefault=none
NodeName=$host CPUs=$(nproc) RealMemory=1000 State=UNKNOWN
PartitionName=test Nodes=$host Default=YES MaxTime=INFINITE State=UP
CONF
stop_cluster() {
  for daemon in slurmd slurmctld; do
    [ -f "$work/slurm/$daemon.pid" ] && kill "$(cat "$work/slurm/$daemon.pid")" 2>/dev/null || true
  done
}
trap stop_cluster EXIT
slurmctld -c || fail "slurmctld did not start"
slurmd || fail "slurmd did not start"
for _ in $(seq 1 60); do
  sinfo -h -o '%t' 2>/dev/null | grep -q idle && break
  sleep 0.5
done
sinfo -h -o '%t' | grep -q idle || fail "the node never came up idle: $(sinfo 2>&1)"
echo "single-node Slurm up on $host (slurmctld port $ctld_port, slurmd port $slurmd_port)"

"$experiment" --config "$team" --seeds 1 --planners hexplore,tspga+ --time-limit-s 20 \
  --results "$work/results" --trace-dir "$work/traces" --emit-slurm "$work/sweep" || fail "--emit-slurm failed"
job=$(sbatch --parsable "$work/sweep/sweep.sbatch") || fail "sbatch refused the sweep"
echo "submitted job array $job"
for _ in $(seq 1 600); do
  [ -z "$(squeue -h -j "$job" 2>/dev/null)" ] && break
  sleep 0.5
done
[ -z "$(squeue -h -j "$job")" ] || fail "the job array did not finish in 300 s"
cat "$work"/sweep/logs/*.log
"$experiment" --gather "$work/sweep" || fail "--gather found runs missing or failed"
rows=$(tail -n +2 "$work/results/comparison.csv" | cut -d, -f1 | tr '\n' ' ')
[ "$rows" = "hexplore tspga+ " ] || fail "comparison.csv rows are '$rows'"
for planner in hexplore tspga+; do
  [ -s "$work/traces/$planner/seed-1/planning-slugcat1.jsonl" ] || fail "no planning trace of $planner"
done
echo "SLURM SWEEP PASS: 2 array tasks ran, the comparison of both was gathered"
