#!/bin/bash
# The error-against-time harness over both renderers (Docs/Deferred.md):
# --bench --quick, TAA rows, forward / deferred / deferred without SSAO /
# deferred with two point lights and a shadowed spot, interleaved for ROUNDS
# rounds so that a slow spell of the machine hits every configuration alike.
# Usage: scripts/bench-renderers.sh [BUILD_DIR] [OUT_DIR] [ROUNDS]
# Then: scripts/bench-renderers.sh --table OUT_DIR prints the table of the doc.
set -euo pipefail
if [ "${1:-}" = "--table" ]; then
  exec python3 - "$2" <<'PY'
import csv, glob, statistics as st, sys
out = sys.argv[1]
cfgs = ["forward", "deferred", "deferred-nossao", "deferred-lit"]
keys = [("taa", "0.300"), ("taa", "0.500"), ("taa", "0.710"), ("taa", "1.000"), ("native", "1.000")]
def rows(path):
    return {(r["filter"], r["scale"]): r for r in csv.DictReader(open(path)) if r["moving"] == "0"}
runs = {c: [rows(d + "/results.csv") for d in sorted(glob.glob(f"{out}/r*_{c}"))] for c in cfgs}
print("| filter, scale | " + " | ".join(cfgs) + " |")
print("| --- |" + " ---: |" * len(cfgs))
for k in keys:
    cells = []
    for c in cfgs:
        got = [r[k] for r in runs[c] if k in r]
        psnr = st.mean(float(r["psnr_db"]) for r in got)
        frame = st.median(float(r["gpu_frame_ms"]) for r in got)
        ratio = [float(r[k]["gpu_frame_ms"]) / float(f[k]["gpu_frame_ms"]) for r, f in zip(runs[c], runs["forward"])]
        cells.append(f"{psnr:.2f} dB, {frame:.1f} ms" + ("" if c == "forward" else f", x{st.median(ratio):.2f} ({min(ratio):.2f}-{max(ratio):.2f})"))
    print(f"| {k[0]} {k[1]} | " + " | ".join(cells) + " |")
PY
fi
build=${1:-build}
out=${2:-bench_renderers}
rounds=${3:-3}
exe="$build/DynamicResolutionRendering/DynamicResolutionRendering"
arena=$(cd "$build/Media/Arena" && pwd)
mkdir -p "$out"
lit="$out/arena_lit.txt"
{
  for e in "arena.gltf NO_ANIM LIT" "bell.gltf bell.gltf LIT" "sky.gltf NO_ANIM UNLIT" "decals.gltf NO_ANIM DECAL" \
           "camera_cinematic.gltf camera_cinematic.gltf CAMERA" "camera_static1.gltf NO_ANIM CAMERA"; do
    set -- $e
    anim=$2
    [ "$anim" != NO_ANIM ] && anim="$arena/$anim"
    echo "$arena/$1 $anim $3"
  done
  echo "LIGHT POINT position=0,150,600 color=3,0.5,0.2 radius=900"
  echo "LIGHT POINT position=-900,200,0 color=0.2,0.6,3 radius=1000"
  echo "LIGHT SPOT position=0,1500,200 direction=0,-1,0 color=4,4,3 radius=3000 angle=25 shadow=1"
} > "$lit"
for round in $(seq 1 "$rounds"); do
  for cfg in forward deferred deferred-nossao deferred-lit; do
    args=(--renderer "${cfg%%-*}")
    [ "$cfg" = deferred-nossao ] && args+=(--no-ssao)
    [ "$cfg" = deferred-lit ] && args+=(--scene "$lit")
    D3DL_VALIDATION=sync "$exe" --bench --quick --validation --filter taa --bench-frames 24 --timing-rounds 4 \
      --no-moving --no-ghosting --no-claims --no-ablations --out "$out/r${round}_$cfg" "${args[@]}" \
      > "$out/r${round}_$cfg.log" 2>&1
    echo "round $round $cfg done"
  done
done
"$0" --table "$out"
