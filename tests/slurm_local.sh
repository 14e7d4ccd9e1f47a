#!/usr/bin/env bash
# The Slurm path for real, on this one machine: starts munged, slurmctld and slurmd from a private
# configuration in a temporary folder (ports 16817/16818), grades a few submissions with
# scripts/grade-slurm (one array task each, then the merge job), checks the merged statuses, and stops
# every daemon it started, by pid, whatever happens.
#
#     SHADOWLAB_SLURM_TEST=1 bash tests/slurm_local.sh BIN
#
# Needs root and Debian's slurmctld, slurmd, slurm-client and munge (not in scripts/setup: a cluster
# has its own Slurm). Without SHADOWLAB_SLURM_TEST=1, or without those, it exits 77 (CTest: skipped).
set -uo pipefail
bin="$(cd "$(dirname "$1")" && pwd)/$(basename "$1")"
src="$(cd "$(dirname "$0")/.." && pwd)"
skip() { echo "SKIP: $*"; exit 77; }
fail() { echo "FAIL: $*"; exit 1; }
[ "${SHADOWLAB_SLURM_TEST:-0}" = 1 ] || skip "set SHADOWLAB_SLURM_TEST=1 to start Slurm daemons here"
[ "$(id -u)" -eq 0 ] || skip "needs root (slurmd runs jobs as their user)"
for t in munged slurmctld slurmd sbatch squeue sinfo; do command -v "$t" >/dev/null || skip "$t not installed"; done

tmp="$(mktemp -d /tmp/shadowlab-slurm.XXXXXX)"
chmod 755 "$tmp"
pids=()
cleanup() {
  for p in "${pids[@]}"; do kill "$p" 2>/dev/null; done
  sleep 1
  for p in "${pids[@]}"; do kill -9 "$p" 2>/dev/null; done
  [ "${SHADOWLAB_SLURM_KEEP:-0}" = 1 ] && echo "kept $tmp" || rm -rf "$tmp"
}
trap cleanup EXIT
host="$(hostname -s)"
mkdir -p "$tmp/munge" "$tmp/state" "$tmp/spool" "$tmp/log"
chmod 700 "$tmp/munge"
dd if=/dev/urandom of="$tmp/munge/munge.key" bs=1024 count=1 status=none
chmod 400 "$tmp/munge/munge.key"
munged --force --key-file="$tmp/munge/munge.key" --socket="$tmp/munge/munge.socket" \
  --pid-file="$tmp/munge/munged.pid" --log-file="$tmp/log/munged.log" --seed-file="$tmp/munge/seed" \
  || fail "munged did not start: $(tail -3 "$tmp/log/munged.log")"
pids+=("$(cat "$tmp/munge/munged.pid")")
cpus=$(nproc)
memory=$(awk '/MemTotal/ { print int($2 / 1024) - 1024 }' /proc/meminfo)
cat >"$tmp/slurm.conf" <<CONF
ClusterName=shadowlabtest
SlurmctldHost=$host
SlurmctldPort=16817
SlurmdPort=16818
SlurmUser=root
AuthType=auth/munge
AuthInfo=socket=$tmp/munge/munge.socket
CredType=cred/munge
StateSaveLocation=$tmp/state
SlurmdSpoolDir=$tmp/spool
SlurmctldPidFile=$tmp/slurmctld.pid
SlurmdPidFile=$tmp/slurmd.pid
SlurmctldLogFile=$tmp/log/slurmctld.log
SlurmdLogFile=$tmp/log/slurmd.log
ProctrackType=proctrack/linuxproc
TaskPlugin=task/none
JobAcctGatherType=jobacct_gather/none
AccountingStorageType=accounting_storage/none
SchedulerType=sched/backfill
SelectType=select/cons_tres
SelectTypeParameters=CR_CPU_Memory
ReturnToService=2
MpiDefault=none
SwitchType=switch/none
NodeName=$host CPUs=$cpus RealMemory=$memory State=UNKNOWN
PartitionName=grading Nodes=$host Default=YES MaxTime=INFINITE State=UP
CONF
export SLURM_CONF="$tmp/slurm.conf"
slurmctld -D -f "$SLURM_CONF" >"$tmp/log/slurmctld.out" 2>&1 &
pids+=($!)
slurmd -D -f "$SLURM_CONF" -N "$host" >"$tmp/log/slurmd.out" 2>&1 &
pids+=($!)
for _ in $(seq 60); do
  sinfo -h -N -o %t 2>/dev/null | grep -q idle && break
  sleep 1
done
sinfo -h -N -o %t 2>/dev/null | grep -q idle || fail "the node never became idle: $(tail -5 "$tmp/log/slurmctld.log" "$tmp/log/slurmd.log")"
echo "slurm up: $(sinfo -h -o '%P %D %c %t')"

# Submissions: the grader's own tree (stock exercises: every lab fails) and generated ones.
subs="$tmp/subs"
python3 "$src/tests/make_submissions.py" --bin "$bin" --out "$subs" --count "${SHADOWLAB_SLURM_SUBMISSIONS:-4}" --seed 15 --labs "${SHADOWLAB_SLURM_LABS:-all}" \
  || fail "could not generate submissions"
chmod -R a+rX "$tmp"
out="$tmp/grades"
SHADOWLAB_BIN="$bin" bash "$src/scripts/grade-slurm" --out "$out" --lab "${SHADOWLAB_SLURM_LABS:-all}" \
  "$subs"/submissions/* || fail "grade-slurm failed"
squeue -h -o '%i %j %T' | head
for _ in $(seq 1800); do
  [ -z "$(squeue -h 2>/dev/null)" ] && break
  sleep 1
done
[ -z "$(squeue -h)" ] || fail "jobs still queued after 30 minutes: $(squeue -h)"
[ -s "$out/results.json" ] || fail "no results.json: $(cat "$out/slurm/merge.out" 2>/dev/null)"
echo "merge exit: $(cat "$out/merge.exit")"
python3 "$src/tests/check_grades.py" "$out" "$subs/expected.json" || fail "statuses differ from the expected ones"
echo "OK: $(ls "$out/slurm" | wc -l) task logs, reports in $out"
