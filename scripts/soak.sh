#!/usr/bin/env bash
# soak.sh [frames] [extra sample options...]: runs drr_soak (Tests/soak) for
# `frames` frames (default 20000) under validation, cycling filters, scales,
# cameras and back-buffer sizes; fails unless RSS and live device objects are
# flat (last quarter within 2 % of the first) with no validation message.
# Not part of CI (tens of minutes on lavapipe). Samples go to $SOAK_CSV.
set -euo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
build="${BUILD_DIR:-$root/build}"
frames=${1:-20000}; shift || true
exec "$build/Tests/soak/drr_soak" --frames "$frames" --csv "${SOAK_CSV:-$build/soak.csv}" "$@"
