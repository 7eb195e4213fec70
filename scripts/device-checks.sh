#!/usr/bin/env bash
# The measurements that need a GPU machine, in one run that fits a lent
# machine's time (each step has its own time limit; the logs go to $OUT):
#   1. temporal upsampling against native and the original's filters, still
#      and moving, at 1920x1080 on the large Arena (Docs/Upscaling.md: the
#      goal is TAAU at 0.71 within 0.5 dB of native on a moving camera at
#      under 60 % of native's GPU frame time);
#   2. where the resolution controller settles with the budget at half the
#      native frame, with and without adaptive tessellation (Docs/Tessellation.md);
#   3. the scene's recording on 2 and 4 threads against 1, large Arena
#      (Docs/Threads.md);
#   4. the RHI's deferred recording on 2 threads against 1, with the
#      hand-written floor (Docs/D3D11-to-Vulkan.md).
# Here, once: scripts/make-bundle.sh .devcarry/bundle
# On the GPU machine, from the repository root, with .devcarry/bundle carried:
#   OUT=/some/dir scripts/device-checks.sh [.devcarry/bundle]
# Env: SIZE (default 1920x1080), STEPS (default "taau tess threads rhi").
set -uo pipefail
bundle=${1:-.devcarry/bundle}
out=${OUT:-device-checks}
size=${SIZE:-1920x1080}
w=${size%x*} h=${size#*x}
mkdir -p "$out"
[ -x "$bundle/run.sh" ] || { echo "device-checks: no bundle at $bundle (scripts/make-bundle.sh $bundle)" >&2; exit 2; }
run() {  # name, limit in seconds, command...
  local name=$1 limit=$2
  shift 2
  local start=$SECONDS
  timeout "$limit" "$@" >"$out/$name.log" 2>&1
  local rc=$?
  echo "$name: exit $rc after $((SECONDS - start)) s" | tee -a "$out/summary.txt"
  tail -n 6 "$out/$name.log"
}
{ date -u; uname -a; nproc; nvidia-smi --query-gpu=name,driver_version,memory.total --format=csv 2>&1; } >"$out/machine.txt"
large="$bundle/media/large/Arena/scene_description.txt"
for step in ${STEPS:-taau tess threads rhi}; do
  case "$step" in
    taau)
      run taau 360 env DRR_ARENA=large "$bundle/run.sh" --headless --bench --out "$out/taau" --width "$w" \
        --height "$h" --camera 1 --filters point,taa,taau,upscale-catmull-rom --scales 0.5,0.71,1.0 \
        --no-claims --no-ghosting --no-ablations --moving-speed 100 --moving-frames 30 --timing-rounds 2 ;;
    tess)
      run tess 240 env DRR_ARENA=large EXE="$bundle/run.sh" W="$w" H="$h" PPE=2 REPEAT=1 CTL_FRAMES=240 \
        scripts/measure-tessellation.sh ;;
    threads)
      # the bundle's run.sh unpacks the large Arena on first use
      [ -f "$large" ] || DRR_ARENA=large "$bundle/run.sh" --help >/dev/null 2>&1
      for t in 2 4; do
        run "threads-$t" 120 env DRR_BIN=drr_scene_record_bench "$bundle/run.sh" --scene "$large" --threads "$t" \
          --pairs 10 --frames 20 --size 640x360
      done ;;
    rhi)
      run rhi 150 env DRR_BIN=drr_rhi_bench "$bundle/run.sh" --deferred --pairs 6 --floor ;;
    *) echo "device-checks: unknown step '$step'" >&2 ;;
  esac
done
