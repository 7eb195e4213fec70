#!/usr/bin/env bash
# Where the resolution controller settles with the budget at half the native
# frame time, forward rendering, without and with adaptive tessellation
# (Docs/Tessellation.md). For each configuration: the native GPU frame
# (--no-dynamic-resolution, median of the last half of NATIVE_FRAMES), then
# the article law in VSync mode with --refresh set to twice the native rate,
# CTL_FRAMES frames; the settled scale is the median of the last third.
# Configurations run one after the other, REPEAT times, interleaved.
#
# usage: scripts/measure-tessellation.sh [build dir] (env: W H PPE MAXF NATIVE_FRAMES CTL_FRAMES REPEAT SCENE)
set -euo pipefail
BUILD=${1:-build}
EXE=$BUILD/DynamicResolutionRendering/DynamicResolutionRendering
W=${W:-320} H=${H:-180} PPE=${PPE:-2} MAXF=${MAXF:-64}
NATIVE_FRAMES=${NATIVE_FRAMES:-30} CTL_FRAMES=${CTL_FRAMES:-240} REPEAT=${REPEAT:-1}
SCENE_ARG=${SCENE:+--scene $SCENE}
TMP=$(mktemp -d)
trap 'rm -rf "$TMP"' EXIT
COMMON="--headless --width $W --height $H --no-gui --camera 1 $SCENE_ARG"
declare -A FLAGS=([off]="" [on]="--tessellation --tess-pixels-per-edge $PPE --max-tess-factor $MAXF")

native_ms() {  # median GPU frame of the last half of a report
  python3 - "$1" <<'PY'
import json, statistics as s, sys
f = [x for x in json.load(open(sys.argv[1]))['frames'] if x.get('gpu_new')]
print("%.2f" % s.median(x['gpu_ms']['frame'] for x in f[len(f) // 2:]))
PY
}
settled() {  # median scale of the last third, its range, GPU frame there
  python3 - "$1" "$2" <<'PY'
import json, statistics as s, sys
f = json.load(open(sys.argv[1]))['frames']; tail = f[-(len(f) // 3):]
sc = [x['scale'][0] for x in tail]; g = [x['gpu_ms']['frame'] for x in tail if x.get('gpu_new')]
print("settled scale %.3f (range %.3f-%.3f), GPU frame %.1f ms against the budget %s ms, %d frames"
      % (s.median(sc), min(sc), max(sc), s.median(g), sys.argv[2], len(f)))
PY
}

echo "lavapipe ${W}x${H}, small Arena, camera 1, article law; tessellation: pixels per edge $PPE, max factor $MAXF"
for r in $(seq "$REPEAT"); do
  for cfg in off on; do
    $EXE $COMMON --frames "$NATIVE_FRAMES" --no-dynamic-resolution ${FLAGS[$cfg]} --report "$TMP/native.json" >/dev/null
    NATIVE=$(native_ms "$TMP/native.json")
    HZ=$(python3 -c "print(round(2000.0 / $NATIVE, 3))")
    BUDGET=$(python3 -c "print(round($NATIVE / 2, 2))")
    $EXE $COMMON --frames "$CTL_FRAMES" --control vsync --refresh "$HZ" --law article ${FLAGS[$cfg]} \
      --report "$TMP/ctl_$cfg.json" >/dev/null
    echo "run $r, tessellation $cfg: native $NATIVE ms; $(settled "$TMP/ctl_$cfg.json" "$BUDGET")"
  done
done
