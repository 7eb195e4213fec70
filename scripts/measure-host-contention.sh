#!/bin/bash
# What two recordings on this host's two CPUs cost each other when they share
# nothing but the machine (Docs/Threads.md): RUNS rounds, each a run of
# drr_scene_record_bench pinned to CPU 0 alone (before-R.txt) and one pinned to
# CPU 0 while a second process, the same benchmark, records on CPU 1 the whole
# time (after-R.txt); the order alternates from round to round. Only the
# 1-thread side of these runs is a measurement: their 2-thread side has both
# threads on CPU 0. scripts/threads-tables.py OUT pairs run R of one setting
# with run R of the other, pair by pair.
# Usage: scripts/measure-host-contention.sh BENCH OUT [RUNS] [SCENE]
set -euo pipefail
[[ $# -ge 2 ]] || { sed -n '2,10p' "$0" >&2; exit 2; }
bench=$1 out=$2 runs=${3:-8}
scene=${4:-build/Media/ArenaProps/scene_description.txt}
source "$(dirname "$0")/recording-args.sh"
check_recording_args measure-host-contention.sh "$runs" "$scene" "$bench"
[[ $(nproc) -ge 2 ]] || { echo "measure-host-contention.sh: needs 2 CPUs, this machine has $(nproc)" >&2; exit 2; }
command -v taskset > /dev/null || { echo "measure-host-contention.sh: needs taskset (util-linux)" >&2; exit 2; }
mkdir -p "$out"
args=(--scene "$scene" --threads 2 --frames 10 --size 64x36)
neighbour=
trap '[[ -n $neighbour ]] && kill "$neighbour" 2> /dev/null; true' EXIT
{ date -u; uptime; } > "$out/load.txt"
for r in $(seq 1 "$runs"); do
  order="before after"
  (( r % 2 == 0 )) && order="after before"
  for side in $order; do
    if [[ $side == after ]]; then
      taskset -c 1 "$bench" "${args[@]}" --pairs 1000 > /dev/null 2>&1 &
      neighbour=$!
      sleep 2  # past its start-up (a whole run of one frame takes 0.7 s): recording
    fi
    taskset -c 0 "$bench" "${args[@]}" --pairs 10 > "$out/$side-$r.txt" 2>&1
    if [[ -n $neighbour ]]; then
      kill "$neighbour" 2> /dev/null || true
      wait "$neighbour" 2> /dev/null || true
      neighbour=
    fi
  done
  { date -u; uptime; } >> "$out/load.txt"
  echo "round $r of $runs done"
done
