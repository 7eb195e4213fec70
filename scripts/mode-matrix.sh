#!/usr/bin/env bash
# mode-matrix.sh BUILD_DIR OUT_DIR [BASELINE_DIR]
#
# Renders the sample's mode matrix headless at a small size, a fixed
# animation time (--time 5 --fixed-dt 0.02: the cameras and objects move, so
# motion blur and the temporal filters see velocity) and a manual scale, one screenshot per mode (OUT_DIR/<mode>.png,
# the GUI left out), enough frames that every temporal history (TAA's pair,
# TAAU's 16-point jitter) has filled. With BASELINE_DIR, compares each
# screenshot with the baseline's of the same name (`idiff -fail 0`: any pixel
# that differs fails) and exits non-zero on any difference or failed run.
#
# Environment: MATRIX_SIZE (default 320x180), MATRIX_FRAMES (default 20),
# MATRIX_EXTRA (options added to every mode, e.g. "--upscale-shader compute"),
# MATRIX_TOLERANCE (idiff's -fail threshold, default 0; 0.004 lets a channel
# differ by one 8-bit step, 1/255, and no more),
# MATRIX_ONLY (a regex of mode names to run), MATRIX_VALIDATION=1 adds
# --validation (slower; a message fails the run), MATRIX_REPORT=1 writes each
# mode's JSON report beside its screenshot (its render targets and passes run).
set -uo pipefail
if [[ $# -lt 2 ]]; then
  echo "usage: $0 BUILD_DIR OUT_DIR [BASELINE_DIR]" >&2
  exit 2
fi
build="$(cd "$1" && pwd)"
out="$2"
baseline="${3:-}"
exe="$build/DynamicResolutionRendering/DynamicResolutionRendering"
[[ -x "$exe" ]] || { echo "no sample at $exe" >&2; exit 2; }
mkdir -p "$out"
size="${MATRIX_SIZE:-320x180}"
frames="${MATRIX_FRAMES:-20}"
common=(--headless --width "${size%x*}" --height "${size#*x}" --frames "$frames" --time 5 --fixed-dt 0.02
        --control manual --scale 0.71 --no-gui --quiet)
[[ "${MATRIX_VALIDATION:-0}" == 1 ]] && common+=(--validation)
read -r -a matrix_extra <<< "${MATRIX_EXTRA:-}"
common+=("${matrix_extra[@]}")
tolerance="${MATRIX_TOLERANCE:-0}"

# name | options (on top of the common ones)
modes=(
  "none|--filter none"
  "point|--filter point"
  "bilinear|--filter bilinear"
  "bicubic|--filter bicubic"
  "noise|--filter noise"
  "noise-offset|--filter noise-offset"
  "taa|--filter taa"
  "taa-noise-offset|--filter taa-noise-offset"
  "taa-basic|--filter taa-basic"
  "bicubic-bspline|--filter bicubic-bspline"
  "upscale-q0|--upscale-quality 0"
  "upscale-q1|--upscale-quality 1"
  "upscale-q2|--upscale-quality 2"
  "upscale-q3|--upscale-quality 3"
  "upscale-q4|--upscale-quality 4"
  "upscale-q5|--upscale-quality 5"
  "taau|--temporal-upsampling"
  "edge-adaptive|--filter upscale-edge-adaptive"
  "taau-fast|--filter taau-fast"
  "none-nomb|--filter none --no-motion-blur"
  "bicubic-nomb|--filter bicubic --no-motion-blur"
  "taa-nomb|--filter taa --no-motion-blur"
  "taa-noise-offset-nomb|--filter taa-noise-offset --no-motion-blur"
  "taau-nomb|--filter taau --no-motion-blur"
  "taa-apiclear|--filter taa --no-ps-clear"
  "bilinear-apiclear-nomb|--filter bilinear --no-ps-clear --no-motion-blur"
  "ss-bicubic|--supersampling --scale 1.4 --filter bicubic"
  "ss-taa|--supersampling --scale 1.3 --filter taa"
  "zoom-bilinear|--filter bilinear --zoom"
  "zoom-taau|--filter taau --zoom"
  "deferred-taa|--renderer deferred --filter taa"
  "deferred-bilinear-nossao|--renderer deferred --no-ssao --filter bilinear"
  "deferred-taau|--renderer deferred --filter taau"
  "deferred-full|--renderer deferred --no-dynamic-resolution"
  "tessellation|--tessellation --filter taa"
  "fix-all-taa|--fix all --filter taa"
  "fix-all-none|--fix all --filter none"
  "fix-all-taa-basic-full|--fix all --no-dynamic-resolution --filter taa-basic"
  "secondary75-catmull|--secondary-screen-percentage 75 --upscale-quality 3"
  "secondary60-taau|--secondary-screen-percentage 60 --filter taau"
  "secondary75-edge|--secondary-screen-percentage 75 --filter upscale-edge-adaptive"
  "full-mb|--no-dynamic-resolution"
  "full-nomb|--no-dynamic-resolution --no-motion-blur"
  "full-taa-basic|--no-dynamic-resolution --filter taa-basic"
  "full-apiclear|--no-dynamic-resolution --no-ps-clear"
  "taa-paused|--filter taa --pause"
  "taa-symmetric|--filter taa --symmetric-taa"
  "marker-bilinear|--filter bilinear --debug-marker-outside"
  "gles2|--preset gles2"
)

# Runs one mode, through lsan-retry.sh: under the sanitizer job, a run whose
# leak check could not run (LeakSanitizer's tracer crashed, nothing reported)
# is run again (at most three runs); its first output stays at the top of the log.
run_mode() {  # name args...
  local name="$1"; shift
  bash "$(dirname "$0")/lsan-retry.sh" "$exe" "$@" > "$out/$name.log" 2>&1
}

ran=0 failed=0 differ=0
for m in "${modes[@]}"; do
  name="${m%%|*}"
  read -r -a extra <<< "${m#*|}"
  [[ -n "${MATRIX_ONLY:-}" && ! "$name" =~ ${MATRIX_ONLY} ]] && continue
  ran=$((ran + 1))
  report=()
  [[ "${MATRIX_REPORT:-0}" == 1 ]] && report=(--report "$out/$name.json")
  if ! run_mode "$name" "${common[@]}" "${extra[@]}" "${report[@]}" --screenshot "$out/$name.png"; then
    echo "FAIL run   $name (see $out/$name.log)"
    failed=$((failed + 1))
    continue
  fi
  if [[ -n "$baseline" ]]; then
    if idiff -fail "$tolerance" -warn "$tolerance" "$baseline/$name.png" "$out/$name.png" > "$out/$name.idiff" 2>&1; then
      echo "same       $name"
    else
      echo "DIFFERENT  $name ($(grep -m1 -E 'Max error|FAILURE|ERROR' "$out/$name.idiff" || echo see "$out/$name.idiff"))"
      differ=$((differ + 1))
    fi
  else
    echo "rendered   $name"
  fi
done
echo "modes $ran, failed runs $failed, different $differ${baseline:+ (against $baseline)}"
[[ $failed -eq 0 && $differ -eq 0 ]]
