#!/usr/bin/env bash
# Installs what is missing, builds everything (warnings are errors:
# DRR_WERROR) and runs the whole test suite (CTest), then the sanitizer job
# (scripts/sanitize.sh: the same suite built with ASan+UBSan, fuzz targets
# included). DRR_SANITIZER_JOB=0 skips the second part for a quicker local
# run; CI (.ci/run) runs both. Prints the time of each phase and job.
set -euo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
start=$(date +%s)
"$root/scripts/setup.sh"
set_up=$(date +%s)
build="${BUILD_DIR:-$root/build}"
BUILD_DIR="$build" "$root/scripts/build.sh" -DDRR_WERROR=ON -DDRR_BUILD_TESTS=ON
built=$(date +%s)
rc=0
(cd "$build" && ctest --output-on-failure --parallel "$(nproc)" --timeout 600) || rc=$?
tested=$(date +%s)
echo "test job: setup $((set_up - start)) s, build $((built - set_up)) s, tests $((tested - built)) s," \
     "total $((tested - start)) s (exit $rc)"
if [ "${DRR_SANITIZER_JOB:-1}" != 0 ]; then
  "$root/scripts/sanitize.sh" || rc=$?
fi
echo "all jobs: $(( $(date +%s) - start )) s (exit $rc)"
exit $rc
