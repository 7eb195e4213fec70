#!/bin/bash
# Two builds of drr_scene_record_bench side by side (Docs/Threads.md): RUNS
# rounds, each a run of the BEFORE binary then one of the AFTER binary, every
# run 10 alternating pairs of 1 thread and 2 threads on SCENE (default: the
# many-object Arena of ./build), then its --contention run (200 frame pairs:
# each chunk beside the other thread against alone). Outputs before-R.txt,
# after-R.txt, contention-before-R.txt and contention-after-R.txt in OUT as
# each run completes; scripts/threads-tables.py OUT pairs run R of one with
# run R of the other, pair by pair, and tables the contention runs.
# Usage: scripts/compare-recording.sh BEFORE_BENCH AFTER_BENCH OUT [RUNS] [SCENE]
set -euo pipefail
[[ $# -ge 3 ]] || { sed -n '2,10p' "$0" >&2; exit 2; }
before=$1 after=$2 out=$3 runs=${4:-4}
scene=${5:-build/Media/ArenaProps/scene_description.txt}
source "$(dirname "$0")/recording-args.sh"
check_recording_args compare-recording.sh "$runs" "$scene" "$before" "$after"
mkdir -p "$out"
{ date -u; uptime; } > "$out/load.txt"
for r in $(seq 1 "$runs"); do
  for side in before after; do
    bench=$before
    [[ $side == after ]] && bench=$after
    "$bench" --scene "$scene" --threads 2 --pairs 10 --frames 10 --size 64x36 > "$out/$side-$r.txt" 2>&1
    "$bench" --contention --scene "$scene" --threads 2 --pairs 10 --frames 20 --size 64x36 \
      > "$out/contention-$side-$r.txt" 2>&1
  done
  { date -u; uptime; } >> "$out/load.txt"
  echo "round $r of $runs done"
done
