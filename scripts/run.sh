#!/usr/bin/env bash
# Installs what is missing, builds what the sample needs, and runs it on its
# default scene. Without a display it runs headless and writes a screenshot
# and a report. Extra arguments go to the sample (see --help).
set -euo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
start=$(date +%s)
"$root/scripts/setup.sh" run
# Only what the sample runs: the program, the import worker it starts for
# every model and texture file, the SPIR-V it loads (drr_shaders) and the
# default scene generated at build time (drr_arena). The last three are
# dependencies of the program already; they are named so that this list says
# what a run needs. scripts/test.sh builds everything else.
BUILD_TARGETS="DynamicResolutionRendering drr_import_worker drr_shaders drr_arena" "$root/scripts/build.sh"
build="${BUILD_DIR:-$root/build}"
echo "run: setup and build took $(( $(date +%s) - start )) s; starting the sample"
if [ -z "${DISPLAY:-}" ] && [ -z "${WAYLAND_DISPLAY:-}" ]; then
  mkdir -p "$root/out"
  echo "run: no display found, running headless (300 frames); output in out/"
  exec "$build/DynamicResolutionRendering/DynamicResolutionRendering" --headless --frames 300 \
    --screenshot "$root/out/screenshot.png" --report "$root/out/report.json" "$@"
fi
exec "$build/DynamicResolutionRendering/DynamicResolutionRendering" "$@"
