#!/usr/bin/env bash
# The measurements that need a GPU machine, in one run that finishes inside
# 5 minutes of command time. Every step has a time limit (they add up to
# 280 s), gives each of its runs only the time the step has left, and appends
# each run's result to its file under $OUT as soon as the run ends, so that a
# run cut short still leaves everything measured until then (checked on
# lavapipe with --small at load average 11: 276 s in all, each step within
# 3 s of its limit; again on a quiet 2-vCPU host: 216 s, the RHI suite's 85
# tests passed under validation, the scene and sample suites cut at their
# share of the step's time, as lavapipe renders them slowly; with the packed
# bundle, unpacked in 1 s: 213 s, the same):
#   a. frame.csv, frame.md: the full frame at 1920x1080 and 3840x2160 on both
#      Arenas (native, point, TAA, TAAU with pixel and, where the sample has
#      --upscale-shader, compute passes; scales 0.5 and 0.71; at 0.71 also the
#      compute TAAU without its group-shared tile and the compute taau-fast,
#      TAAU's faster permutation), in interleaved
#      rounds, each run's first WARMUP_MS of real time dropped; per-pass
#      GPU medians (frame, scene, post, upscale pass); frame / native and
#      TAAU's pass / point's (Docs/Upscaling.md: the goals 0.60 and 2.5);
#   b. power.txt: paced runs (--pace-hz 60) at scales 1.0, 0.71, 0.5 with the
#      board power (nvidia-smi power.draw every 100 ms) sampled through each;
#      the frame interval of each (a paced run holds 16.7 ms);
#   c. threads.txt: scene recording on 2 and 4 threads against 1 on the
#      default and the many-object Arena, 2 threads also with a 2 ms idle
#      pause before each frame (as behind VSync), and the automatic mode on
#      the default Arena (drr_scene_record_bench; Docs/Threads.md), with the
#      frames split by whether the workers started before the draw list;
#   d. psnr.csv: the frames of Docs/results/lavapipe-frames rendered here,
#      PSNR against the stored lavapipe render;
#   e. tests.txt: the RHI, scene and sample render suites (core + sync
#      validation in every fixture), passed and failed tests.
# A machine whose NVIDIA driver has only its EGL library registered gets an
# ICD file written for it (as Docs/results/h100-controller/run.sh does).
#
# Here, once: scripts/make-bundle.sh .devcarry/bundle --with-validation
# (the bundle unpacks in place when it runs: check this script here on a copy
# of it, or make it again before carrying it)
# On the GPU machine, from the repository root, with .devcarry/bundle carried:
#   OUT=/some/dir scripts/device-checks.sh [BUNDLE] [--small]
# --small: 320x180 and 640x360, fewer frames (a check of the script itself on
# lavapipe). Env: STEPS (default "frame power threads psnr tests"), ROUNDS
# (frame rounds, default 3; a round is cut when the step's time runs out).
set -uo pipefail
here="$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)"
root="$(dirname "$here")"
bundle=.devcarry/bundle
small=0
for a in "$@"; do
  case "$a" in
    --small) small=1 ;;
    -*) echo "device-checks: unknown option '$a'" >&2; exit 2 ;;
    *) bundle="$a" ;;
  esac
done
bundle="$(cd "$bundle" 2>/dev/null && pwd)" || { echo "device-checks: no bundle folder" >&2; exit 2; }
[ -x "$bundle/run.sh" ] || { echo "device-checks: no bundle at $bundle (scripts/make-bundle.sh $bundle)" >&2; exit 2; }
out="$(mkdir -p "${OUT:-device-checks}" && cd "${OUT:-device-checks}" && pwd)"
report() { python3 "$here/device-report.py" "$@"; }
# Per-step limits in seconds: 115 + 45 + 35 + 30 + 55 = 280 (each step
# may end a second or two late: the summaries after its last run).
declare -A limit=([frame]=115 [power]=45 [threads]=35 [psnr]=30 [tests]=55)
if ((small)); then
  sizes="320x180 640x360" frames=12 warmup_ms=0 record_size=160x90 record_runs="--pairs 3 --frames 5"
  power_size=320x180 power_arena=default power_frames=60 per_record_run=25
else
  sizes="1920x1080 3840x2160" frames=90 warmup_ms=500 record_size=640x360 record_runs="--pairs 5 --frames 10"
  power_size=3840x2160 power_arena=large power_frames=240 per_record_run=10
fi
# Line-buffered output, so that a run killed at its limit leaves its lines.
linebuf=()
command -v stdbuf >/dev/null && linebuf=(stdbuf -oL -eL)
rounds=${ROUNDS:-3}

# The time the current step has left (its deadline is set by begin).
left() { echo $((deadline - SECONDS)); }
begin() { step=$1 deadline=$((SECONDS + limit[$1])) step_start=$SECONDS; echo "== $step (limit ${limit[$1]} s)"; }
finish() { echo "$step: done after $((SECONDS - step_start)) s of ${limit[$step]}" | tee -a "$out/summary.txt"; }
# Runs a command with the step's remaining time (at most $1 seconds when given as --max N).
bounded() {
  local max=100000
  if [ "$1" = --max ]; then max=$2; shift 2; fi
  local t=$(($(left) < max ? $(left) : max))
  ((t >= 2)) || return 124
  timeout "$t" "$@"
}
sample() { bounded "$bundle/run.sh" --headless --no-gui "$@"; }

# --- the Vulkan driver -------------------------------------------------------
find_driver() {
  command -v nvidia-smi >/dev/null || return 0
  local icds=(/usr/share/vulkan/icd.d/*.json /etc/vulkan/icd.d/*.json)
  grep -qil nvidia "${icds[@]}" 2>/dev/null && return 0
  local egl
  egl="$(ldconfig -p | awk '/libEGL_nvidia\.so\.0/ {print $NF; exit}')"
  [ -n "$egl" ] || { echo "no NVIDIA Vulkan ICD and no libEGL_nvidia.so.0" >>"$out/machine.txt"; return 0; }
  printf '{"file_format_version":"1.0.0","ICD":{"library_path":"%s","api_version":"1.3.0"}}\n' "$egl" >"$out/nvidia_icd.json"
  export VK_DRIVER_FILES="$out/nvidia_icd.json" VK_ICD_FILENAMES="$out/nvidia_icd.json"
  echo "ICD written for $egl" >>"$out/machine.txt"
}

# Paths of the Arenas in the bundle; the large one is unpacked on first use.
arena_path() {
  case "$1" in
    default) echo "$bundle/Media/Arena/scene_description.txt" ;;
    props) echo "$bundle/Media/ArenaProps/scene_description.txt" ;;
    large)
      "$bundle/unpack.sh" large >&2
      echo "$bundle/Media/ArenaLarge/scene_description.txt" ;;
  esac
}

# --- a. full frame -------------------------------------------------------------
frame_configs() {
  echo "native --no-dynamic-resolution"
  local s
  for s in 0.5 0.71; do
    echo "point-$s --filter point --scale $s"
    echo "taa-$s --filter taa --scale $s"
    if ((compute)); then
      echo "taau-pixel-$s --filter taau --scale $s --upscale-shader pixel"
      echo "taau-compute-$s --filter taau --scale $s --upscale-shader compute"
      [ "$s" = 0.71 ] && [ -n "$direct_shaders" ] &&
        echo "taau-direct-$s --filter taau --scale $s --upscale-shader compute --shader-dir $direct_shaders"
      # TAAU's faster permutation, where the bundle's sample has it.
      [ "$s" = 0.71 ] && [ -f "$bundle/shaders/UpscaleTemporal_TemporalUpsampleFastCS.spv" ] &&
        echo "taau-fast-compute-$s --filter taau-fast --scale $s --upscale-shader compute"
    else
      echo "taau-pixel-$s --filter taau --scale $s"
    fi
  done
}
# A copy of the bundle's shaders whose compute TAAU is its version without the
# group-shared tile (taau-direct-0.71: does the tile pay on this device?).
direct_shaders=""
make_direct_shaders() {
  local spv=UpscaleTemporal_TemporalUpsample
  [ -f "$bundle/shaders/${spv}DirectCS.spv" ] || return 0
  rm -rf "$out/shaders-direct" && cp -r "$bundle/shaders" "$out/shaders-direct" &&
    cp "$bundle/shaders/${spv}DirectCS.spv" "$out/shaders-direct/${spv}CS.spv" && direct_shaders="$out/shaders-direct"
}
step_frame() {
  begin frame
  ((compute)) && make_direct_shaders
  local csv="$out/frame.csv" r size arena name args
  echo "round,size,arena,config,frames,frame_ms,scene_ms,postp_ms,scale_ms" >"$csv"
  for ((r = 1; r <= rounds; ++r)); do
    for size in $sizes; do
      for arena in default large; do
        while read -r name args; do
          (($(left) >= 2)) || break 4
          # shellcheck disable=SC2086
          if sample --scene "$(arena_path $arena)" --width "${size%x*}" --height "${size#*x}" --camera 1 \
              --frames "$frames" $args --report "$out/run.json" >"$out/frame-run.log" 2>&1; then
            echo "$r,$size,$arena,$name,$(report frame-row "$out/run.json" "$warmup_ms")" >>"$csv"
            grep -q '^adapter' "$out/machine.txt" || report adapter "$out/run.json" >>"$out/machine.txt"
          else
            echo "$r,$size,$arena,$name,0,nan,nan,nan,nan" >>"$csv"
          fi
        done < <(frame_configs)
      done
    done
  done
  report frame-summary "$csv" >"$out/frame.md" 2>&1
  finish
}

# --- b. paced runs and board power -------------------------------------------------
step_power() {
  begin power
  local s arena size=$power_size smi=0 pid
  command -v nvidia-smi >/dev/null && smi=1
  ((smi)) || echo "no nvidia-smi: frame intervals only" >>"$out/power.txt"
  arena=$(arena_path $power_arena)
  for s in 1.0 0.71 0.5; do
    (($(left) >= 4)) || break
    ((smi)) && { nvidia-smi --query-gpu=power.draw --format=csv,noheader,nounits -lms 100 >"$out/power-$s.csv" 2>&1 & pid=$!; }
    sample --scene "$arena" --width "${size%x*}" --height "${size#*x}" --camera 1 --pace-hz 60 --control manual \
      --scale "$s" --frames "$power_frames" --report "$out/paced-$s.json" >"$out/power-run.log" 2>&1
    local rc=$?
    ((smi)) && { kill "$pid" 2>/dev/null; wait "$pid" 2>/dev/null; }
    if ((rc == 0)); then
      local samples=()
      ((smi)) && samples=("$out/power-$s.csv")
      echo "scale $s, 60 Hz paced, $size $power_arena Arena: $(report paced "$out/paced-$s.json" "${samples[@]}")" \
        >>"$out/power.txt"
    else
      echo "scale $s: exit $rc" >>"$out/power.txt"
    fi
  done
  finish
}

# --- c. recording threads -----------------------------------------------------
# Each run: ARENA:THREADS:IDLE_MS (0 threads = automatic; an idle pause before
# each timed frame, as behind VSync: Docs/Threads.md, "2026-12-07").
step_threads() {
  begin threads
  local run arena t idle
  for run in props:2:0 props:2:2 props:4:0 default:2:0 default:4:0 default:0:0; do
    IFS=: read -r arena t idle <<<"$run"
    (($(left) >= 3)) || break
    # shellcheck disable=SC2086
    DRR_BIN=drr_scene_record_bench bounded --max $per_record_run "$bundle/run.sh" --scene "$(arena_path $arena)" \
      --threads "$t" --idle-ms "$idle" $record_runs --size "$record_size" >"$out/threads-run.log" 2>&1
    echo "$arena Arena, threads $t (0 = automatic), idle pause $idle ms, exit $?:" \
      "$(grep -E '^ratio|thread\(s\): (chunk|every worker running)' "$out/threads-run.log" | tr '\n' ' ')" \
      >>"$out/threads.txt"
  done
  finish
}

# --- d. the stored lavapipe frames ------------------------------------------------
step_psnr() {
  begin psnr
  local refs="$root/Docs/results/lavapipe-frames" name arena args
  echo "frame,psnr_db" >"$out/psnr.csv"
  mkdir -p "$out/frames"
  while read -r name arena args; do
    [[ -z "$name" || "$name" == \#* ]] && continue
    (($(left) >= 3)) || break
    # shellcheck disable=SC2086
    if sample --scene "$(arena_path "$arena")" $args --screenshot "$out/frames/$name.png" >"$out/psnr-run.log" 2>&1; then
      echo "$name,$(report psnr "$refs/$name.png" "$out/frames/$name.png")" >>"$out/psnr.csv"
    else
      echo "$name,exit $?" >>"$out/psnr.csv"
    fi
  done <"$refs/frames.txt"
  finish
}

# --- e. test suites under validation -------------------------------------------------
# The suites read the build's Media and shader folders at the path they were
# built at: that path is made a link to the bundle when it does not exist.
link_build_path() {
  local built
  built="$(cat "$bundle/build-path" 2>/dev/null)" || return 0
  [ -e "$built" ] || { mkdir -p "$(dirname "$built")" 2>/dev/null && ln -s "$bundle" "$built"; } ||
    echo "cannot link $built to the bundle: tests that read the build's files fail" >>"$out/tests.txt"
}
step_tests() {
  begin tests
  link_build_path
  local suite count
  set -- drr_rhi_tests drr_scene_render_tests drr_sample_render_tests
  count=$#
  for suite; do
    (($(left) >= 3)) || break
    D3DL_VALIDATION=sync DRR_TEST_OUT="$out/tests-$suite-files" DRR_BIN="$suite" bounded --max $(($(left) / count)) "${linebuf[@]}" "$bundle/run.sh" >"$out/tests-$suite.log" 2>&1
    local rc=$?
    echo "$suite: exit $rc, $(grep -c '^\[       OK \]' "$out/tests-$suite.log") passed," \
      "$(grep -c '^\[  FAILED  \].*ms)$' "$out/tests-$suite.log") failed:" \
      "$(grep -E '^\[  FAILED  \].*ms\)$' "$out/tests-$suite.log" | awk '{print $4}' | tr '\n' ' ')" >>"$out/tests.txt"
    count=$((count - 1))
  done
  finish
}

start=$SECONDS
{ date -u; uname -a; nproc; uptime; nvidia-smi --query-gpu=name,driver_version,power.limit --format=csv 2>&1; } \
  >"$out/machine.txt"
find_driver
# The bundle's programs and Arenas travel packed; unpack them before any step
# reads them (a few seconds, outside the steps' limits).
unpack_start=$SECONDS
if [ -x "$bundle/unpack.sh" ]; then
  "$bundle/unpack.sh" || { echo "device-checks: the bundle at $bundle does not unpack" >&2; exit 2; }
  echo "bundle unpacked in $((SECONDS - unpack_start)) s" >>"$out/machine.txt"
fi
compute=0
"$bundle/run.sh" --help 2>/dev/null | grep -q -- --upscale-shader && compute=1
for s in ${STEPS:-frame power threads psnr tests}; do
  case "$s" in
    frame | power | threads | psnr | tests) "step_$s" ;;
    *) echo "device-checks: unknown step '$s'" >&2 ;;
  esac
done
echo "device-checks: $((SECONDS - start)) s in all" | tee -a "$out/summary.txt"
