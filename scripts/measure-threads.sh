#!/bin/bash
# Recording threads on lavapipe (Docs/Threads.md): drr_scene_record_bench,
# 1 thread against N in alternating pairs, RUNS runs of 10 pairs each, one
# after the other, every run's output kept as it completes:
#   props-R.txt      the many-object Arena (2,938 draws), 2 threads against 1
#   auto-R.txt       the Arena (59 draws), the automatic mode against 1 thread
#   arena2-R.txt     the Arena, 2 threads against 1 (below the threshold)
#   props-N-R.txt    the Arena with N props (--detail props), 2 threads against 1:
#                    where two threads start to pay (the automatic mode's threshold)
# Usage: scripts/measure-threads.sh [BUILD_DIR] [OUT_DIR] [RUNS] [PROPS...]
# Then: scripts/threads-tables.py OUT_DIR [--write Docs/Threads.md]
set -euo pipefail
build=${1:-build}
out=${2:-threads_out}
runs=${3:-5}
shift $(( $# < 3 ? $# : 3 ))
props=("$@")
[[ ${#props[@]} -gt 0 ]] || props=(600 1200 2000)
bench="$build/Tests/recording/drr_scene_record_bench"
gen="$build/DynamicResolutionRendering/tools/drr_arenagen"
[[ -x "$bench" && -x "$gen" ]] || { echo "measure-threads.sh: build $bench and $gen first" >&2; exit 2; }
mkdir -p "$out"
common=(--pairs 10 --frames 10 --size 64x36)
arena=(--scene "$build/Media/Arena/scene_description.txt" --pairs 10 --frames 20 --size 64x36)  # 59 draws: more frames
for n in "${props[@]}"; do
  [[ -f "$out/scenes/props-$n/scene_description.txt" ]] ||
    "$gen" --detail props --props "$n" --out "$out/scenes/props-$n" > /dev/null
done
{ date -u; uptime; } > "$out/load.txt"
for r in $(seq 1 "$runs"); do
  "$bench" --scene "$build/Media/ArenaProps/scene_description.txt" --threads 2 "${common[@]}" > "$out/props-$r.txt" 2>&1
  "$bench" "${arena[@]}" --threads 0 > "$out/auto-$r.txt" 2>&1
  "$bench" "${arena[@]}" --threads 2 > "$out/arena2-$r.txt" 2>&1
  for n in "${props[@]}"; do
    "$bench" --scene "$out/scenes/props-$n/scene_description.txt" --threads 2 "${common[@]}" > "$out/props-$n-$r.txt" 2>&1
  done
  { date -u; uptime; } >> "$out/load.txt"
  echo "run $r of $runs done"
done
rm -rf "$out/scenes"
