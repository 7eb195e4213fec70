#!/usr/bin/env bash
# soak.sh [frames] [extra sample options...]: runs drr_soak (Tests/soak) for
# `frames` frames (default 20000) under validation, cycling filters, scales,
# cameras and back-buffer sizes; fails unless RSS and live device objects are
# flat (last quarter within 2 % of the first) with no validation message.
# Not part of CI (tens of minutes on lavapipe). Samples go to $SOAK_CSV.
#
# soak.sh --rss FRAMES [--report] [extra sample options...]: runs the sample
# executable itself (its application loop, Run) headless at 32x18 for FRAMES
# frames, with or without --report, and samples its resident memory (VmRSS)
# once a second. After a warm-up (the first 10 % of the samples, at least
# $SOAK_WARMUP_S, default 30: scene load, shader and pipeline creation), the
# rest is cut into ten windows of equal length; growth is the highest sample
# of the last window less the highest of the first, and must stay within
# $SOAK_RSS_SLACK_KIB (default 1024). Peaks, not single samples: on lavapipe
# the resident set dips by about 5.7 MiB and comes back every 10 to 15 s
# (memory handed back to the system and touched again), and a sample taken
# in a dip would read as growth.
# Prints the samples' summary (the band and each window's peak); the series
# goes to $SOAK_CSV (default $build/soak-rss.csv).
set -euo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
build="${BUILD_DIR:-$root/build}"

if [[ "${1:-}" != "--rss" ]]; then
  frames=${1:-20000}; shift || true
  exec "$build/Tests/soak/drr_soak" --frames "$frames" --csv "${SOAK_CSV:-$build/soak.csv}" "$@"
fi

shift
frames=${1:?usage: soak.sh --rss FRAMES [--report] [sample options...]}
shift
args=(--headless --width 32 --height 18 --frames "$frames" --no-gui --quiet)
tmp="$(mktemp -d)"
trap 'rm -rf "$tmp"' EXIT
if [[ "${1:-}" == "--report" ]]; then
  args+=(--report "$tmp/report.json")
  shift
fi
csv="${SOAK_CSV:-$build/soak-rss.csv}"
slack=${SOAK_RSS_SLACK_KIB:-1024}
exe="$build/DynamicResolutionRendering/DynamicResolutionRendering"

start=$(date +%s)
"$exe" "${args[@]}" "$@" > "$tmp/run.log" 2>&1 &
pid=$!
echo "seconds,rss_kib" > "$csv"
while kill -0 "$pid" 2> /dev/null; do
  rss=$(awk '/^VmRSS:/ {print $2}' "/proc/$pid/status" 2> /dev/null || true)
  [[ -n "$rss" ]] && echo "$(($(date +%s) - start)),$rss" >> "$csv"
  sleep 1
done
rc=0
wait "$pid" || rc=$?
seconds=$(($(date +%s) - start))
if [[ $rc -ne 0 ]]; then
  echo "the sample failed (exit code $rc):"; tail -20 "$tmp/run.log"
  exit 1
fi
report_bytes=0
[[ -f "$tmp/report.json" ]] && report_bytes=$(stat -c %s "$tmp/report.json")
# After the warm-up: the band, each tenth's peak, and the growth of the peaks.
awk -F, -v slack="$slack" -v warmup="${SOAK_WARMUP_S:-30}" -v frames="$frames" -v seconds="$seconds" -v report="$report_bytes" '
  NR > 1 { v[++n] = $2 }
  END {
    w = int(n / 10); if (w < warmup) w = warmup
    if (n - w < 10) { print "too few samples (" n ") after the " warmup " s warm-up: run more frames"; exit 1 }
    lo = v[w + 1]; hi = lo; m = n - w; peaks = ""
    for (k = 0; k < 10; ++k) {
      p = 0
      for (i = w + 1 + int(k * m / 10); i <= w + int((k + 1) * m / 10); ++i) {
        if (v[i] > p) p = v[i]; if (v[i] < lo) lo = v[i]; if (v[i] > hi) hi = v[i]
      }
      peak[k] = p; peaks = peaks (k ? " " : "") p
    }
    printf "frames %d in %d s, %d samples (warm-up %d): RSS band %d..%d KiB, peak per tenth %s KiB, " \
           "growth of the peaks %d KiB (limit %d)%s\n", frames, seconds, n, w, lo, hi, peaks, peak[9] - peak[0], slack,
           (report > 0 ? sprintf(", report %d bytes", report) : "")
    exit ((peak[9] - peak[0] <= slack) ? 0 : 1)
  }' "$csv"
