#!/usr/bin/env bash
# Submits a meshquilt batch manifest as a Slurm array job: task i of N runs the jobs whose index is
# i modulo N (meshquilt batch reads SLURM_ARRAY_TASK_ID/MIN/STEP/COUNT), so the manifest is never
# split. Prints the Slurm job id. Rerunning it after a failure or a lost node redoes only the jobs
# without a matching completion record.
#
#   scripts/slurm/submit.sh MANIFEST [--tasks N] [--cpus C] [--mem SIZE] [--jobs K] [--time LIMIT]
#                           [--partition P] [--meshquilt PATH] [--log-dir DIR] [--wait] [-- SBATCH_ARGS...]
#
#   --tasks N      array tasks (default: one per job, at most the number of jobs)
#   --cpus C       CPUs per task (default 4); each job is pinned to C/K of them
#   --mem SIZE     memory per task, as sbatch --mem takes it (default 8G); synth's default memory
#                  budget is 3/4 of it (the cgroup limit)
#   --jobs K       jobs running at once inside a task (default 1)
#   --time LIMIT   time limit per task (sbatch --time)
#   --partition P  Slurm partition
#   --meshquilt P  the meshquilt executable (default: meshquilt on PATH, else build/cli/meshquilt)
#   --log-dir DIR  where each task's output goes (default: MANIFEST.batch/ beside the manifest)
#   --wait         wait for every task to end (sbatch --wait); the exit code is sbatch's
set -euo pipefail

usage() { sed -n '2,20p' "$0" | sed 's/^# \{0,1\}//' >&2; exit 2; }
[ $# -ge 1 ] || usage
manifest=$1
shift
tasks=0 cpus=4 mem=8G jobs=1 time_limit="" partition="" meshquilt="" log_dir="" wait_flag=()
while [ $# -gt 0 ]; do
  case "$1" in
    --tasks) tasks=$2; shift 2 ;;
    --cpus) cpus=$2; shift 2 ;;
    --mem) mem=$2; shift 2 ;;
    --jobs) jobs=$2; shift 2 ;;
    --time) time_limit=$2; shift 2 ;;
    --partition) partition=$2; shift 2 ;;
    --meshquilt) meshquilt=$2; shift 2 ;;
    --log-dir) log_dir=$2; shift 2 ;;
    --wait) wait_flag=(--wait); shift ;;
    --) shift; break ;;
    -h|--help) usage ;;
    *) echo "submit.sh: unknown option $1" >&2; usage ;;
  esac
done

if [ -z "$meshquilt" ]; then
  meshquilt=$(command -v meshquilt || true)
  [ -n "$meshquilt" ] || meshquilt="$(cd "$(dirname "$0")/../.." && pwd)/build/cli/meshquilt"
fi
[ -x "$meshquilt" ] || { echo "submit.sh: $meshquilt: not an executable (use --meshquilt)" >&2; exit 3; }
meshquilt=$(realpath "$meshquilt")
manifest=$(realpath "$manifest")

# Checks the manifest here, before anything is queued: a bad line fails now, not on the cluster.
count=$("$meshquilt" batch "$manifest" --count)
if [ "$tasks" -le 0 ] || [ "$tasks" -gt "$count" ]; then tasks=$count; fi
threads=$(( cpus / jobs ))
[ "$threads" -ge 1 ] || threads=1
[ -n "$log_dir" ] || log_dir="$manifest.batch"
mkdir -p "$log_dir"

args=(--parsable --job-name=meshquilt-batch --array="0-$((tasks - 1))" --cpus-per-task="$cpus" --mem="$mem"
      --output="$log_dir/slurm-%A_%a.out" --chdir="$(dirname "$manifest")")
[ -z "$time_limit" ] || args+=(--time="$time_limit")
[ -z "$partition" ] || args+=(--partition="$partition")
printf -v command '%q ' "$meshquilt" batch "$manifest" --jobs "$jobs" --threads "$threads" --progress json
sbatch "${args[@]}" "${wait_flag[@]}" "$@" --wrap="exec $command"
