#!/usr/bin/env bash
# A design optimisation of `afsv optimize afs` (chapter 4), `afsv optimize hps` (chapter 6:
# the GA over the front struts, then the re-evaluation over terrain seeds) or `afsv
# optimize layout` (any suspension layout) on a Slurm cluster, one job array per batch of
# design points (hps: of vehicle runs), the array index being the shard:
#
#   loop:  afsv optimize PROBLEM OPTIONS --state STATE --ask BATCH      (on the submit host)
#          sbatch --array=1-SHARDS --wait THIS_SCRIPT task ...          (array task I runs
#                 afsv batch evaluate BATCH --shard I/SHARDS -o results-I.jsonl)
#          afsv optimize PROBLEM OPTIONS --state STATE --tell results-*.jsonl
#   until the batch file's header says "finished": true; then the report
#   (the in-process run's JSON) is in WORKDIR/report.json.
#
# Usage:
#   scripts/slurm/optimize.sh afs|hps|layout [afsv optimize PROBLEM OPTIONS...]
# Environment:
#   AFSV         the afsv binary, visible from every node (default: afsv on PATH)
#   SHARDS       array tasks per batch (default 4)
#   WORKDIR      state, batches, results, logs, report; on a shared file system
#                (default ./PROBLEM-optimize-run)
#   SBATCH_OPTS  extra sbatch options, e.g. "--partition=short --time=00:10:00"
#
# The state file WORKDIR/state.json is the single source of truth: if the driver is
# stopped, run the script again with the same options and WORKDIR and it continues from
# the last batch told (an asked batch is asked again, the same points with the same ids).
# A failed array task makes `sbatch --wait` fail and stops the script. A report that is
# "not earned" (afsv exit 3: no feasible design, an hps optimum above the a_wz limit, or a
# layout variable on its bound) is
# still written to WORKDIR/report.json, and the script exits 3 too.
# Documentation: docs/optimisation.md, "Running on a cluster". Tested end to end on a
# single-node Slurm by `cargo xtask slurm-test` (both problems).
set -euo pipefail

if [[ "${1:-}" == "task" ]]; then
    # One array task: evaluate shard SLURM_ARRAY_TASK_ID of the batch.
    afsv=$2 batch=$3 shards=$4 out=$5
    i=${SLURM_ARRAY_TASK_ID:?task mode runs as a Slurm array task}
    exec "$afsv" --quiet batch evaluate "$batch" --shard "$i/$shards" \
        -o "$out/results-$i.jsonl" --json
fi

problem=${1:-}
case "$problem" in
    afs | hps | layout) shift ;;
    *)
        echo "usage: $0 afs|hps|layout [afsv optimize PROBLEM OPTIONS...]" >&2
        exit 2
        ;;
esac
AFSV=${AFSV:-afsv}
SHARDS=${SHARDS:-4}
WORKDIR=${WORKDIR:-./$problem-optimize-run}
SBATCH_OPTS=${SBATCH_OPTS:-}
mkdir -p "$WORKDIR/logs"
WORKDIR=$(cd "$WORKDIR" && pwd)
AFSV=$(command -v "$AFSV")
script=$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)/$(basename "${BASH_SOURCE[0]}")
state=$WORKDIR/state.json
batch=$WORKDIR/batch.jsonl

while true; do
    rc=0
    "$AFSV" --quiet optimize "$problem" "$@" --state "$state" --ask "$batch" --json \
        > "$WORKDIR/ask.json" || rc=$?
    if head -n 1 "$batch" | grep -q '"finished":true'; then
        mv "$WORKDIR/ask.json" "$WORKDIR/report.json"
        echo "$problem-optimize: finished; report in $WORKDIR/report.json" >&2
        exit "$rc"
    fi
    if [[ $rc -ne 0 ]]; then
        exit "$rc"
    fi
    n=$(head -n 1 "$batch" | sed -n 's/.*"batch":\([0-9]*\).*/\1/p')
    echo "$problem-optimize: batch $n: $(grep -c '"id"' "$batch") points in $SHARDS shards" >&2
    # Results of an earlier batch would be refused by --tell; clear them first.
    rm -f "$WORKDIR"/results-*.jsonl
    # shellcheck disable=SC2086 # SBATCH_OPTS is a list of options
    sbatch --quiet --wait --array="1-$SHARDS" --job-name="$problem-optimize" \
        --chdir="$WORKDIR" --output="$WORKDIR/logs/batch-$n-%a.out" $SBATCH_OPTS \
        "$script" task "$AFSV" "$batch" "$SHARDS" "$WORKDIR"
    results=()
    for i in $(seq 1 "$SHARDS"); do
        results+=("$WORKDIR/results-$i.jsonl")
    done
    "$AFSV" --quiet optimize "$problem" "$@" --state "$state" --tell "${results[@]}" --json \
        > "$WORKDIR/tell.json"
done
