#!/usr/bin/env bash
# A real single-node Slurm on localhost: munged with a generated key, slurmctld and slurmd with a
# generated slurm.conf, everything (state, spool, sockets, logs) in a temporary folder, all as
# root. Submits a manifest of 8 small planar jobs as an array of 4 tasks with
# scripts/slurm/submit.sh, waits for it, checks every output against a direct `synth` run and the
# report, and stops the daemons by their pids. Outside CI a Slurm that cannot start skips (77);
# with CI=true it fails.
#   tests/batch_slurm_test.sh MESHQUILT SOURCE_DIR
set -uo pipefail
cli=$1
source_dir=$2
started=$(date +%s)

skip() {
  if [ "${CI:-}" = true ]; then echo "FAIL (CI=true): $*" >&2; exit 1; fi
  echo "SKIP: $*" >&2
  exit 77
}
fail() { echo "FAIL: $*" >&2; exit 1; }

[ "$(id -u)" = 0 ] || skip "starting slurmd needs root"
for tool in munged slurmctld slurmd sbatch sinfo scontrol scancel python3; do
  command -v "$tool" >/dev/null || skip "$tool is not installed (scripts/install-deps.sh installs slurm-wlm and munge)"
done

tmp=$(mktemp -d /tmp/meshquilt_slurm.XXXXXX)
chmod 700 "$tmp"
export SLURM_CONF=$tmp/slurm.conf
job_id=""

pid_of() { [ -s "$1" ] && cat "$1"; }
cleanup() {
  local code=$?
  [ -z "$job_id" ] || scancel "$job_id" 2>/dev/null
  for pid_file in "$tmp/slurmd.pid" "$tmp/slurmctld.pid" "$tmp/munged.pid"; do
    pid=$(pid_of "$pid_file") || continue
    kill "$pid" 2>/dev/null
    for _ in $(seq 50); do kill -0 "$pid" 2>/dev/null || break; sleep 0.1; done
    kill -0 "$pid" 2>/dev/null && kill -9 "$pid" 2>/dev/null
  done
  if [ "$code" != 0 ] && [ "$code" != 77 ]; then
    for log in "$tmp"/*.log; do echo "--- $log" >&2; tail -n 20 "$log" >&2; done
    for out in "$tmp"/work/jobs.jsonl.batch/slurm-*.out; do [ -f "$out" ] && { echo "--- $out" >&2; tail -n 5 "$out" >&2; }; done
  fi
  rm -rf "$tmp"
  exit "$code"
}
trap cleanup EXIT

# Two free TCP ports for slurmctld and slurmd (so parallel runs and a system Slurm do not clash).
read -r ctld_port slurmd_port < <(python3 -c '
import socket
s = [socket.socket() for _ in range(2)]
for x in s: x.bind(("127.0.0.1", 0))
print(*[x.getsockname()[1] for x in s])')

head -c 1024 /dev/urandom > "$tmp/munge.key"
chmod 400 "$tmp/munge.key"
munged --force --key-file="$tmp/munge.key" --socket="$tmp/munge.socket" --pid-file="$tmp/munged.pid" \
  --log-file="$tmp/munged.log" --seed-file="$tmp/munged.seed" || skip "munged did not start"

host=$(hostname -s)
mkdir -p "$tmp/state" "$tmp/spool"
cat > "$SLURM_CONF" <<CONF
ClusterName=meshquilt$$
SlurmctldHost=$host(127.0.0.1)
SlurmctldPort=$ctld_port
SlurmdPort=$slurmd_port
AuthType=auth/munge
CredType=cred/munge
AuthInfo=socket=$tmp/munge.socket
SlurmUser=root
SlurmdUser=root
StateSaveLocation=$tmp/state
SlurmdSpoolDir=$tmp/spool
SlurmctldPidFile=$tmp/slurmctld.pid
SlurmdPidFile=$tmp/slurmd.pid
SlurmctldLogFile=$tmp/slurmctld.log
SlurmdLogFile=$tmp/slurmd.log
ProctrackType=proctrack/linuxproc
TaskPlugin=task/none
JobAcctGatherType=jobacct_gather/none
AccountingStorageType=accounting_storage/none
JobCompType=jobcomp/none
SwitchType=switch/none
MpiDefault=none
SchedulerType=sched/builtin
SelectType=select/cons_tres
SelectTypeParameters=CR_CPU
SlurmdParameters=config_overrides
ReturnToService=2
MailProg=/bin/true
NodeName=mqnode NodeHostname=$host NodeAddr=127.0.0.1 CPUs=4 RealMemory=4000 State=UNKNOWN
PartitionName=mq Nodes=mqnode Default=YES MaxTime=INFINITE State=UP
CONF

slurmctld -i -f "$SLURM_CONF" || skip "slurmctld did not start"
slurmd -f "$SLURM_CONF" -N mqnode || skip "slurmd did not start"
state=""
for _ in $(seq 60); do
  state=$(sinfo -h -n mqnode -o %T 2>/dev/null | head -n1)
  [ "$state" = idle ] && break
  sleep 0.5
done
[ "$state" = idle ] || skip "the Slurm node did not become idle (state '$state')"
echo "slurm up in $(( $(date +%s) - started )) s"

# Eight small planar jobs (--max-patches keeps each under a second). A curved job is one more line once synth has --base.
work=$tmp/work
mkdir -p "$work"
"$cli" swatch chainmail --preset small -o "$work/chain.ply" >/dev/null || fail "swatch chainmail"
"$cli" swatch weave --pattern twill:2/3 --preset small -o "$work/twill.ply" >/dev/null || fail "swatch weave"
jobs=(
  'out/chain1.ply|["--swatch", "chain.ply", "--plane", "1x1", "--seed", 1, "--backend", "cpu", "--max-patches", 3]'
  'out/chain2.ply|["--swatch", "chain.ply", "--plane", "1x1", "--seed", 2, "--backend", "cpu", "--max-patches", 3]'
  'out/twill3.ply|["--swatch", "twill.ply", "--plane", "1x1", "--seed", 3, "--backend", "cpu", "--max-patches", 3]'
  'out/twill4.obj|["--swatch", "twill.ply", "--plane", "1x1", "--seed", 4, "--backend", "cpu", "--max-patches", 3]'
  'out/chain5.ply|{"swatch": "chain.ply", "plane": "1.5x1", "seed": 5, "backend": "cpu", "max-patches": 3, "stats": "out/chain5.json"}'
  'out/twill6.off|{"swatch": "twill.ply", "plane": "1x1.5", "seed": 6, "backend": "cpu", "max-patches": 3}'
  'out/builtin7.ply|["--plane", "1x1", "--seed", 7, "--backend", "cpu", "--max-patches", 3]'
  'out/chain8.stl|["--swatch", "chain.ply", "--plane", "1x1", "--seed", 8, "--backend", "cpu", "--cells", "12", "--max-patches", 3]'
)
: > "$work/jobs.jsonl"
for job in "${jobs[@]}"; do
  printf '{"output": "%s", "options": %s}\n' "${job%%|*}" "${job#*|}" >> "$work/jobs.jsonl"
done

job_id=$(bash "$source_dir/scripts/slurm/submit.sh" "$work/jobs.jsonl" --tasks 4 --cpus 1 --mem 500M \
  --meshquilt "$cli" --wait) || fail "the array job failed (sbatch --wait)"
job_id=${job_id%%;*}
echo "array job $job_id done after $(( $(date +%s) - started )) s"
tasks=$(ls "$work"/jobs.jsonl.batch/slurm-*.out | wc -l)
[ "$tasks" -ge 4 ] || fail "expected 4 task logs, found $tasks"
grep -h '"event":"batch_end"' "$work"/jobs.jsonl.batch/slurm-*.out | grep -q '"shard":"3/4"' || fail "no task ran shard 3/4"
report=$("$cli" batch "$work/jobs.jsonl" --report --format csv) || fail "report says not complete: $report"
[ "$(echo "$report" | grep -c ',done,')" = 8 ] || fail "report: $report"

# Every output byte-identical to a direct synth run of the same job.
mkdir -p "$work/direct/out"
for job in "${jobs[@]}"; do
  output=${job%%|*}
  mapfile -t options < <(python3 -c '
import json, sys
o = json.loads(sys.argv[1])
if isinstance(o, dict):
    args = []
    for k, v in o.items():
        args += ["--" + k, str(v)]
    o = args
print("\n".join(str(x) for x in o))' "${job#*|}")
  for i in "${!options[@]}"; do
    case "${options[$i]}" in *.ply|*.json) options[$i]=$(realpath -m "$work/${options[$i]}" | sed "s#$work/out/#$work/direct/out/#") ;; esac
  done
  (cd "$work" && "$cli" synth "${options[@]}" --progress none -o "$work/direct/$output" >/dev/null) || fail "direct synth of $output"
  cmp "$work/$output" "$work/direct/$output" || fail "$output differs from a direct synth run"
done
echo "PASS: 8 jobs in 4 Slurm array tasks, identical to direct synth, in $(( $(date +%s) - started )) s"
