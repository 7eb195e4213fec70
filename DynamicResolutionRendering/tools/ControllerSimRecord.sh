#!/usr/bin/env bash
# Records the held-out GPU-time traces of drr_controller_sim --trace from real
# runs of the sample (headless; on this project's machines lavapipe).
# usage: ControllerSimRecord.sh BUILD_DIR OUT_DIR
# Per scene: a scale sweep with the animation paused (the cost curve t(s) the
# replay scales recorded times by), then runs with the cinematic or a static
# camera, at a fixed scale or with a law on, animation at a fixed 1/60 s per
# frame. The budget of the law runs is the sweep's median time at scale 0.7.
set -euo pipefail
build=$(realpath "$1"); out=$(realpath -m "$2"); mkdir -p "$out"
app="$build/DynamicResolutionRendering/DynamicResolutionRendering"
conv="$(dirname "$(realpath "$0")")/ControllerSimTrace.py"
tmp=$(mktemp -d); trap 'rm -rf "$tmp"' EXIT
held="held-out trace: never used for tuning any law (Docs/Controller.md)"

run() {  # name role args...
  local name=$1 role=$2; shift 2
  "$app" --headless --quiet --report "$tmp/$name.json" "$@" > /dev/null
  python3 "$conv" "$tmp/$name.json" "$tmp/$name.csv" "$role" "DynamicResolutionRendering $*"
}

sweep() {  # name args...: scales 1.0 .. 0.3, 30 frames each, the first 10 dropped
  local name=$1; shift
  : > "$out/$name-sweep.csv"
  for s in 1.0 0.9 0.8 0.7 0.6 0.5 0.4 0.3; do
    run "sw$s" "cost curve sweep ($held)" --pause --scale "$s" --frames 30 "$@"
    if [ ! -s "$out/$name-sweep.csv" ]; then grep '^#' "$tmp/sw$s.csv" | sed "s/--scale $s/--scale S (S = 1.0 0.9 .. 0.3)/" >> "$out/$name-sweep.csv"; echo "frame,scale,gpu_ms" >> "$out/$name-sweep.csv"; fi
    grep -v '^#' "$tmp/sw$s.csv" | tail -n +2 | awk -F, '$1 >= 10' >> "$out/$name-sweep.csv"
  done
}

refresh_for() {  # Hz whose period is the sweep's median time at scale 0.7
  python3 - "$1" <<'PY'
import statistics, sys
t = [float(l.split(",")[2]) for l in open(sys.argv[1]) if l[0].isdigit() and abs(float(l.split(",")[1]) - 0.7) < 0.01]
print(f"{1000.0 / statistics.median(t):.4f}")
PY
}

trace() {  # name args...
  local name=$1; shift
  run "$name" "$held" --fixed-dt 0.0166667 --frames 500 "$@"
  cp "$tmp/$name.csv" "$out/$name.csv"
}

arena=(--width 1280 --height 720)
large=(--scene "$build/Media/ArenaLarge/scene_description.txt" --width 960 --height 540)
sweep arena "${arena[@]}" --camera 1
r=$(refresh_for "$out/arena-sweep.csv")
trace arena-cinematic-fixed "${arena[@]}" --camera 1 --scale 1.0
trace arena-cinematic-robust "${arena[@]}" --camera 1 --control vsync --refresh "$r" --law robust
trace arena-static-article "${arena[@]}" --camera 2 --control vsync --refresh "$r" --law article
sweep large "${large[@]}" --camera 1
r=$(refresh_for "$out/large-sweep.csv")
trace large-cinematic-ue "${large[@]}" --camera 1 --control vsync --refresh "$r" --law ue-style
echo "traces in $out"
