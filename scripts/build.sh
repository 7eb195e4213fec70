#!/usr/bin/env bash
# Configures and builds into BUILD_DIR (default: build). Used by run.sh and
# test.sh. Arguments go to CMake's configure step. BUILD_TARGETS (names
# separated by spaces) builds those targets and what they depend on only;
# unset, everything is built.
#
# The default build type is Release at -O2: the same code as CMake's
# RelWithDebInfo (-O2 -DNDEBUG), without its debug information, which costs
# about a third of each unit's compile time and most of the link time on a
# first build. BUILD_TYPE=RelWithDebInfo (or Debug) for a debugger.
set -euo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
build="${BUILD_DIR:-$root/build}"
cmake -S "$root" -B "$build" -G Ninja -DCMAKE_BUILD_TYPE="${BUILD_TYPE:-Release}" \
  -DCMAKE_CXX_FLAGS_RELEASE="-O2 -DNDEBUG" -DCMAKE_C_FLAGS_RELEASE="-O2 -DNDEBUG" "$@" >/dev/null
targets=()
if [ -n "${BUILD_TARGETS:-}" ]; then
  read -r -a names <<<"$BUILD_TARGETS"
  targets=(--target "${names[@]}")
fi
cmake --build "$build" --parallel "$(nproc)" "${targets[@]}"
