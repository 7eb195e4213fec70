#!/usr/bin/env bash
# Installs what is missing, builds, and runs the whole test suite (CTest),
# then the sanitizer job (scripts/sanitize.sh: the same suite built with
# ASan+UBSan, fuzz targets included). DRR_SANITIZER_JOB=0 skips the second
# part for a quicker local run; CI (.ci/run) runs both.
set -euo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
"$root/scripts/setup.sh"
start=$(date +%s)
BUILD_DIR="${BUILD_DIR:-$root/build}" "$root/scripts/build.sh"
build="${BUILD_DIR:-$root/build}"
built=$(date +%s)
(cd "$build" && ctest --output-on-failure --parallel "$(nproc)" --timeout 600)
tested=$(date +%s)
echo "test job: build $((built - start)) s, tests $((tested - built)) s"
if [ "${DRR_SANITIZER_JOB:-1}" != 0 ]; then
  "$root/scripts/sanitize.sh"
fi
echo "all jobs: $(( $(date +%s) - start )) s"
