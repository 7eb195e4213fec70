#!/bin/bash
# The OpenGL ES 2.0 article's claims (Docs/GLES2.md):
# the bench with --preset gles2 (bilinear quad to (f, f), no clamp, no TAA, no
# motion blur, API clear), bilinear at 1.0, 0.75, 0.625, 0.5, 0.25 and native
# (the scene straight into the back buffer), four still views and the moving
# cinematic camera at x1; interleaved timing rounds with rotating order. The
# size has whole viewports at every factor (320x176: 240x132, 200x110, 160x88,
# 80x44), where the port's texture coordinates (viewport / target) are the
# article's (f, f) exactly. Rows are written as each completes.
# Then the overhead alone (bilinear 1.0 against native, still views, no moving
# camera, OVERHEAD_ROUNDS interleaved rounds) into OUT_DIR-overhead.
# Usage: scripts/measure-gles2.sh [BUILD_DIR] [OUT_DIR] [ROUNDS] [OVERHEAD_ROUNDS]
# Then: scripts/gles2-tables.py OUT_DIR,OUT_DIR-overhead [--write Docs/GLES2.md]
set -euo pipefail
build=${1:-build}
out=${2:-gles2_out}
rounds=${3:-6}
overhead_rounds=${4:-12}
exe="$build/DynamicResolutionRendering/DynamicResolutionRendering"
mkdir -p "$out"
{ date -u; uptime; } > "$out/load.txt"
"$exe" --bench --preset gles2 --out "$out" --width 320 --height 176 \
  --filters bilinear --scales 1.0,0.75,0.625,0.5,0.25 \
  --no-claims --no-ghosting --no-ablations \
  --moving-speed 100 --moving-frames 24 --moving-warmup 8 \
  --bench-warmup 6 --bench-warmup-ms 0 --bench-frames 2 \
  --timing-rounds "$rounds" --timing-warmup-ms 300 2>&1 | tee "$out/log.txt"
{ date -u; uptime; } >> "$out/load.txt"
mkdir -p "$out-overhead"
{ date -u; uptime; } > "$out-overhead/load.txt"
"$exe" --bench --preset gles2 --out "$out-overhead" --width 320 --height 176 --filters bilinear --scales 1.0 \
  --no-moving --no-claims --no-ghosting --no-ablations --bench-warmup 6 --bench-warmup-ms 0 --bench-frames 2 \
  --timing-rounds "$overhead_rounds" --timing-warmup-ms 300 2>&1 | tee "$out-overhead/log.txt"
{ date -u; uptime; } >> "$out-overhead/load.txt"
