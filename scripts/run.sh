#!/usr/bin/env bash
# Installs what is missing, builds, and runs the sample on its default scene.
# Without a display it runs headless and writes a screenshot and a report.
# Extra arguments go to the sample (see --help).
set -euo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
"$root/scripts/setup.sh"
"$root/scripts/build.sh"
build="${BUILD_DIR:-$root/build}"
if [ -z "${DISPLAY:-}" ] && [ -z "${WAYLAND_DISPLAY:-}" ]; then
  mkdir -p "$root/out"
  echo "run: no display found, running headless (300 frames); output in out/"
  exec "$build/DynamicResolutionRendering/DynamicResolutionRendering" --headless --frames 300 \
    --screenshot "$root/out/screenshot.png" --report "$root/out/report.json" "$@"
fi
exec "$build/DynamicResolutionRendering/DynamicResolutionRendering" "$@"
