#!/usr/bin/env bash
# Where the resolution controller settles with the budget at half the native
# frame time, forward rendering, without and with adaptive tessellation
# (Docs/Tessellation.md). For each configuration: the native GPU frame
# (--no-dynamic-resolution, median of the last half of NATIVE_FRAMES), then
# the article law in VSync mode with --refresh set to twice the native rate,
# CTL_FRAMES frames; the settled scale is the median of the last third.
# Configurations run one after the other, REPEAT times, interleaved.
# With SWEEP="1.0 0.8 ..." it instead measures the GPU frame at those fixed
# scales (SWEEP_FRAMES each, median of the last half; ROUNDS rounds, the two
# configurations interleaved at each scale) and prints where the median curve
# crosses half its value at the first scale: where the article law settles
# (Controller.md), without the controller's own noise.
#
# With ONE_BUDGET=DIR both modes are judged at one absolute budget, half the
# untessellated native frame (see below; scripts/tessellation-tables.py).
#
# usage: scripts/measure-tessellation.sh [build dir]
#        (env: W H PPE MAXF NATIVE_FRAMES CTL_FRAMES REPEAT SCENE SWEEP SWEEP_FRAMES ROUNDS EXE ONE_BUDGET)
set -euo pipefail
BUILD=${1:-build}
EXE=${EXE:-$BUILD/DynamicResolutionRendering/DynamicResolutionRendering}  # or a bundle's run.sh
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

sweep_rounds() {  # SCALES FILE: ROUNDS rounds of the fixed scales, both modes interleaved; "round cfg scale ms" lines
  for r in $(seq "${ROUNDS:-2}"); do
    for s in $1; do
      for cfg in off on; do
        $EXE $COMMON --frames "${SWEEP_FRAMES:-16}" --scale "$s" ${FLAGS[$cfg]} --report "$TMP/s.json" >/dev/null
        echo "$r $cfg $s $(native_ms "$TMP/s.json")" | tee -a "$2"
      done
    done
  done
}

echo "${W}x${H}, ${SCENE:-the ${DRR_ARENA:-small} Arena}, camera 1, article law; tessellation: pixels per edge $PPE, max factor $MAXF"
if [ -n "${ONE_BUDGET:-}" ]; then
  # One absolute budget for both modes: half the untessellated native frame
  # (median of NATIVE_FRAMES, once). Into the folder ONE_BUDGET, a line per
  # measurement as it completes (scripts/tessellation-tables.py reads them):
  #   budget.txt   native_off_ms budget_ms refresh_hz
  #   sweep.txt    round cfg scale gpu_frame_ms     (SWEEP scales, interleaved)
  #   settled.txt  cfg settled_scale lo hi gpu_frame_ms frames
  #   bench_<cfg>/ the bench at the settled scale (PSNR, FLIP against that mode's reference)
  OUT=$ONE_BUDGET; mkdir -p "$OUT"
  { date -u; uptime; } >> "$OUT/load.txt"
  $EXE $COMMON --frames "$NATIVE_FRAMES" --no-dynamic-resolution --report "$TMP/native.json" >/dev/null
  NATIVE=$(native_ms "$TMP/native.json")
  BUDGET=$(python3 -c "print(round($NATIVE / 2, 2))")
  HZ=$(python3 -c "print(round(1000.0 / $BUDGET, 3))")
  echo "$NATIVE $BUDGET $HZ" | tee "$OUT/budget.txt"
  sweep_rounds "${SWEEP:-1.0 0.85 0.71 0.55 0.4}" "$OUT/sweep.txt"
  for cfg in off on; do
    $EXE $COMMON --frames "$CTL_FRAMES" --control vsync --refresh "$HZ" --law article ${FLAGS[$cfg]} \
      --report "$TMP/ctl_$cfg.json" >/dev/null
    python3 - "$TMP/ctl_$cfg.json" "$cfg" <<'PY' | tee -a "$OUT/settled.txt"
import json, statistics as s, sys
f = json.load(open(sys.argv[1]))['frames']; tail = f[-(len(f) // 3):]
sc = [x['scale'][0] for x in tail]; g = [x['gpu_ms']['frame'] for x in tail if x.get('gpu_new')]
print("%s %.3f %.3f %.3f %.2f %d" % (sys.argv[2], s.median(sc), min(sc), max(sc), s.median(g), len(f)))
PY
  done
  while read -r cfg scale _; do
    $EXE --bench --out "$OUT/bench_$cfg" --width "$W" --height "$H" --camera 1 --scales "$scale" --filters taa \
      ${FLAGS[$cfg]} $SCENE_ARG --no-claims --no-ghosting --no-ablations --no-moving --bench-warmup 6 \
      --bench-warmup-ms 0 --bench-frames 2 --timing-rounds 0 >/dev/null 2>&1 || echo "bench $cfg failed"
  done < "$OUT/settled.txt"
  { date -u; uptime; } >> "$OUT/load.txt"
  exit 0
fi
if [ -n "${SWEEP:-}" ]; then
  sweep_rounds "$SWEEP" "$TMP/sweep.txt"
  python3 - "$TMP/sweep.txt" <<'PY'
import statistics as st, sys, collections
d = collections.defaultdict(list)
for line in open(sys.argv[1]):
    _, cfg, s, ms = line.split(); d[(cfg, float(s))].append(float(ms))
for cfg in ("off", "on"):
    pts = sorted((s, st.median(v)) for (c, s), v in d.items() if c == cfg)
    top = pts[-1][1]; half = top / 2
    print(cfg + ": " + ", ".join("%.2f: %.1f ms" % p for p in pts))
    cross = None
    for (s0, t0), (s1, t1) in zip(pts, pts[1:]):
        if t0 <= half <= t1 and t1 > t0: cross = s0 + (half - t0) / (t1 - t0) * (s1 - s0)
    print("  t(%.2f)/2 = %.1f ms is crossed at scale %s" % (pts[-1][0], half, "%.3f" % cross if cross else "below %.2f" % pts[0][0]))
PY
  exit 0
fi
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
