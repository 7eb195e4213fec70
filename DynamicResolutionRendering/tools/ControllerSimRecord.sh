#!/usr/bin/env bash
# Records GPU-time traces for drr_controller_sim from real runs of the sample
# (headless; on this project's machines lavapipe).
# usage: ControllerSimRecord.sh BUILD_DIR OUT_DIR [held-out|tuning|fresh]
#   held-out (default): the held-out set (Tests/controller/traces), never used for tuning;
#   tuning: traces that the robust law's tuning scan may use
#           (Tests/controller/tuning-traces, drr_controller_sim --scan-robust --tuning-traces);
#   fresh: a second held-out set recorded after both laws were tuned and frozen
#          (Tests/controller/fresh-traces): the Arena only, every law run given
#          half the time of the fixed-scale run at scale 1 recorded just before
#          it, so the scale works off its floor at the load of the moment.
# Every new file records the machine's load (uptime) before and after its run:
# on a shared machine the load, not the scene, sets most of the GPU time.
# Per scene: a scale sweep with the animation paused (the cost curve t(s) the
# replay scales recorded times by), then runs with the cinematic or a static
# camera, at a fixed scale or with a law on, animation at a fixed 1/60 s per
# frame. The budget of the law runs is the sweep's median time at scale 0.7
# (first runs; on a loaded machine that pinned them at the minimum scale) or
# half the median time of a fixed-scale run at scale 1 (later runs).
# Files that exist already are kept (re-run to add the missing ones).
set -euo pipefail
build=$(realpath "$1"); out=$(realpath -m "$2"); mkdir -p "$out"
app="$build/DynamicResolutionRendering/DynamicResolutionRendering"
conv="$(dirname "$(realpath "$0")")/ControllerSimTrace.py"
tmp=$(mktemp -d); trap 'rm -rf "$tmp"' EXIT
mode=${3:-held-out}
case $mode in
  held-out|fresh) held="held-out trace: never used for tuning any law (Docs/Controller.md)" ;;
  tuning) held="tuning trace: recorded for tuning the robust law, not held out (Docs/Controller.md)" ;;
  *) echo "ControllerSimRecord.sh: mode must be held-out, tuning or fresh, not '$mode'" >&2; exit 2 ;;
esac

run() {  # name role args...
  local name=$1 role=$2; shift 2
  local before; before=$(uptime)
  "$app" --headless --quiet --report "$tmp/$name.json" "$@" > /dev/null
  python3 "$conv" "$tmp/$name.json" "$tmp/$name.csv" "$role" "DynamicResolutionRendering ${*//$build/BUILD}"
  sed -i "1a # machine load before (uptime):$before\\n# machine load after (uptime):$(uptime); cores: $(nproc)" "$tmp/$name.csv"
}

sweep() {  # name args...: scales 1.0 .. 0.3, 30 frames each, the first 10 dropped, renumbered
  local name=$1; shift
  [ -e "$out/$name-sweep.csv" ] && return
  : > "$tmp/sweep.csv"
  for s in 1.0 0.9 0.8 0.7 0.6 0.5 0.4 0.3; do
    run "sw$s" "cost curve sweep ($held)" --pause --scale "$s" --frames 30 "$@"
    if [ ! -s "$tmp/sweep.csv" ]; then grep '^#' "$tmp/sw$s.csv" | sed "s/--scale $s/--scale S (S = 1.0 0.9 .. 0.3)/" >> "$tmp/sweep.csv"; echo "frame,scale,gpu_ms" >> "$tmp/sweep.csv"; fi
    grep -v '^#' "$tmp/sw$s.csv" | tail -n +2 | awk -F, '$1 >= 10' >> "$tmp/sweep.csv"
  done
  awk -F, 'BEGIN { OFS = "," } /^[0-9]/ { $1 = n++ } { print }' "$tmp/sweep.csv" > "$out/$name-sweep.csv"
}

refresh_for() {  # Hz whose period is FACTOR x the median time at SCALE in FILE
  python3 - "$1" "$2" "$3" <<'PY'
import statistics, sys
path, scale, factor = sys.argv[1], float(sys.argv[2]), float(sys.argv[3])
t = [float(l.split(",")[2]) for l in open(path) if l[0].isdigit() and abs(float(l.split(",")[1]) - scale) < 0.01]
print(f"{1000.0 / (factor * statistics.median(t)):.4f}")
PY
}

trace() {  # name args...
  local name=$1; shift
  [ -e "$out/$name.csv" ] && return
  run "$name" "$held" --fixed-dt 0.0166667 --frames 500 "$@"
  cp "$tmp/$name.csv" "$out/$name.csv"
}

arena=(--width 1280 --height 720)
large=(--scene "$build/Media/ArenaLarge/scene_description.txt" --width 960 --height 540)
if [ "$mode" = tuning ]; then  # other cameras and scales than the held-out runs, fixed scales only
  sweep arena "${arena[@]}" --camera 2
  trace arena-cinematic-fixed08 "${arena[@]}" --camera 1 --scale 0.8
  trace arena-static2-fixed07 "${arena[@]}" --camera 2 --scale 0.7
  trace arena-static3-fixed05 "${arena[@]}" --camera 3 --scale 0.5
  trace arena-cinematic-fixed09 "${arena[@]}" --camera 1 --scale 0.9
  echo "traces in $out"; exit 0
fi
if [ "$mode" = fresh ]; then
  sweep arena "${arena[@]}" --camera 1
  trace arena-cinematic-fixed10 "${arena[@]}" --camera 1 --scale 1.0
  r=$(refresh_for "$out/arena-cinematic-fixed10.csv" 1.0 0.5)
  trace arena-cinematic-robust "${arena[@]}" --camera 1 --control vsync --refresh "$r" --law robust
  trace arena-cinematic-ue "${arena[@]}" --camera 1 --control vsync --refresh "$r" --law ue-style
  trace arena-static2-article "${arena[@]}" --camera 2 --control vsync --refresh "$r" --law article
  trace arena-static3-fixed07 "${arena[@]}" --camera 3 --scale 0.7
  trace arena-static2-fixed085 "${arena[@]}" --camera 2 --scale 0.85
  echo "traces in $out"; exit 0
fi
sweep arena "${arena[@]}" --camera 1
r=$(refresh_for "$out/arena-sweep.csv" 0.7 1)
trace arena-cinematic-fixed "${arena[@]}" --camera 1 --scale 1.0
trace arena-cinematic-robust "${arena[@]}" --camera 1 --control vsync --refresh "$r" --law robust
trace arena-static-article "${arena[@]}" --camera 2 --control vsync --refresh "$r" --law article
sweep large "${large[@]}" --camera 1
r=$(refresh_for "$out/large-sweep.csv" 0.7 1)
trace large-cinematic-ue "${large[@]}" --camera 1 --control vsync --refresh "$r" --law ue-style
# Later runs: fixed scales other than 1, and laws with half the full-scale time as budget.
trace arena-cinematic-fixed06 "${arena[@]}" --camera 1 --scale 0.6
trace arena-static3-fixed08 "${arena[@]}" --camera 3 --scale 0.8
r=$(refresh_for "$out/arena-cinematic-fixed.csv" 1.0 0.5)
trace arena-cinematic-ue2 "${arena[@]}" --camera 1 --control vsync --refresh "$r" --law ue-style
trace arena-static3-robust2 "${arena[@]}" --camera 3 --control vsync --refresh "$r" --law robust
trace large-static-fixed07 "${large[@]}" --camera 2 --scale 0.7
echo "traces in $out"
