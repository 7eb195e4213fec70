#!/usr/bin/env bash
# Builds a self-contained bundle of the sample for a Linux x86-64 machine that
# has a Vulkan driver but none of the project's Debian packages (for example a
# bare GPU server): the binaries, their non-system shared libraries (Debian's),
# the compiled shaders, the Arenas (default, many-object and large), the
# benches, the RHI, scene and sample render test suites with their shaders,
# and run.sh: what scripts/device-checks.sh runs. All but run.sh and
# unpack.sh travel packed (payload.tar.xz; the large Arena and the validation
# layer each in an .xz of their own) and are expanded on first use, in place:
# a bundle that has run here is no longer small, so try one out on a copy.
#
#   scripts/make-bundle.sh [OUT_DIR] [--with-validation] [--from-build DIR]
#
# --from-build DIR: copy from that (already built) build folder instead of
# building the Release one (a check of the bundle's layout; such a bundle
# carries OpenImageIO's libraries and is much larger).
#
# Images go through stb (-DDRR_IMAGE_IO=STB): OpenImageIO's dependency closure
# is hundreds of megabytes. On the target: OUT_DIR/run.sh [sample options].
set -euo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
out="$root/bundle"
validation=0
build="$root/build-bundle"
from_build=0
while (($#)); do
  case "$1" in
    --with-validation) validation=1 ;;
    --from-build) build="$(cd "$2" && pwd)"; from_build=1; shift ;;
    -*) echo "make-bundle: unknown option '$1'" >&2; exit 2 ;;
    *) out="$1" ;;
  esac
  shift
done
suites=(Tests/rhi/drr_rhi_tests Tests/scene/drr_scene_render_tests Tests/sample/drr_sample_render_tests)

if ((!from_build)); then
  "$root/scripts/setup.sh"
  cmake -S "$root" -B "$build" -G Ninja -DCMAKE_BUILD_TYPE=Release -DDRR_IMAGE_IO=STB -DDRR_BUILD_TESTS=ON >/dev/null
  cmake --build "$build" --parallel "$(nproc)" \
    --target DynamicResolutionRendering drr_import_worker drr_rhi_bench drr_scene_record_bench drr_arena \
    drr_arena_large drr_arena_props "${suites[@]##*/}"
fi

rm -rf "$out"
mkdir -p "$out/bin" "$out/lib" "$out/Media"
# drr_import_worker decodes model and texture files; the sample and the test
# suites look for it beside themselves.
cp "$build/DynamicResolutionRendering/DynamicResolutionRendering" "$build/DynamicResolutionRendering/drr_import_worker" \
   "$build/Tests/recording/drr_rhi_bench" "$build/Tests/recording/drr_scene_record_bench" "$out/bin/"
for suite in "${suites[@]}"; do cp "$build/$suite" "$out/bin/"; done
# An OpenImageIO build (--from-build) opens its image module beside the executable.
if [ -f "$build/lib/libdrr_imageio_oiio.so" ]; then cp "$build/lib/libdrr_imageio_oiio.so" "$out/bin/"; fi
strip "$out"/bin/*
# The folders keep the build's names: the suites read them at the build's
# path, which scripts/device-checks.sh links to the bundle (build-path).
cp -r "$build/shaders" "$out/shaders"
cp -r "$build/test-shaders" "$out/test-shaders"
echo "$build" >"$out/build-path"
mkdir -p "$out/bench-shaders" && cp "$build"/Tests/recording/shaders/*.spv "$out/bench-shaders/"
cp -r "$build/Media/Arena" "$build/Media/ArenaProps" "$out/Media/"
tar -C "$build/Media" -cJf "$out/Media/ArenaLarge.tar.xz" ArenaLarge

# Shared libraries except the C/C++ runtime, which every target system has.
system='^(libc|libm|libstdc\+\+|libgcc_s|ld-linux-x86-64|libpthread|libdl|librt)\.so'
for bin in "$out"/bin/*; do
  ldd "$bin" | awk '/=>/ && $3 ~ /^\// {print $3}'
done | sort -u | while read -r lib; do
  name="$(basename "$lib")"
  [[ "$name" =~ $system ]] || cp -L "$lib" "$out/lib/$name"
done
# The RHI suite reads copies of a few sources beside itself.
cp -r "$build/Tests/rhi/rhi-test-sources" "$out/bin/"
# The programs, libraries, shaders and the two small Arenas travel as one
# .tar.xz (a fifth of their size: a bundle carried to a GPU machine must stay
# small), which unpack.sh expands beside itself on first use.
payload=(bin lib shaders test-shaders bench-shaders Media/Arena Media/ArenaProps)
tar -C "$out" -cf - "${payload[@]}" | xz -9 -T0 >"$out/payload.tar.xz"
(cd "$out" && rm -rf "${payload[@]}")
if ((validation)); then
  # The layer is large (22 MB); it travels compressed and unpack.sh expands it.
  mkdir -p "$out/layers"
  xz -9 -c /usr/lib/x86_64-linux-gnu/libVkLayer_khronos_validation.so >"$out/layers/libVkLayer_khronos_validation.so.xz"
  sed 's|"library_path": *"[^"]*"|"library_path": "./libVkLayer_khronos_validation.so"|' \
    /usr/share/vulkan/explicit_layer.d/VkLayer_khronos_validation.json >"$out/layers/VkLayer_khronos_validation.json"
fi

cat >"$out/unpack.sh" <<'UNPACK'
#!/usr/bin/env bash
# Expands what the bundle carries packed, once each, beside this script:
# payload.tar.xz and the validation layer always, the large Arena when called
# as `unpack.sh large`. A part is marked done only once it is whole; calls
# that overlap wait for the first (flock, where the machine has it).
here="$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)"
large=0
[ "${1:-}" = large ] && large=1
done_all() { [ -f "$here/.unpacked" ] && { ((!large)) || [ -f "$here/Media/.large-unpacked" ]; }; }
done_all && exit 0
exec 9>"$here/.unpack.lock"
if command -v flock >/dev/null; then flock 9; fi
fail() { echo "bundle: cannot unpack $1" >&2; exit 1; }
if [ ! -f "$here/.unpacked" ]; then
  tar -C "$here" -xJf "$here/payload.tar.xz" || fail "$here/payload.tar.xz"
  layer="$here/layers/libVkLayer_khronos_validation.so"
  if [ -f "$layer.xz" ]; then xz -dc "$layer.xz" >"$layer" || fail "$layer.xz"; fi
  touch "$here/.unpacked"
fi
if ((large)) && [ ! -f "$here/Media/.large-unpacked" ]; then
  tar -C "$here/Media" -xJf "$here/Media/ArenaLarge.tar.xz" || fail "$here/Media/ArenaLarge.tar.xz"
  mkdir -p "$here/Media/large" && ln -sfn ../ArenaLarge "$here/Media/large/Arena" || fail "the large Arena's link"
  touch "$here/Media/.large-unpacked"
fi
UNPACK
chmod +x "$out/unpack.sh"

cat >"$out/run.sh" <<'RUN'
#!/usr/bin/env bash
# Runs the bundled sample (arguments as for DynamicResolutionRendering --help),
# or DRR_BIN (a bench or a test suite of bin/). DRR_ARENA=large uses the
# large Arena (unpacked on first use).
here="$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)"
if [ "${DRR_ARENA:-small}" = large ]; then "$here/unpack.sh" large; else "$here/unpack.sh"; fi || exit 1
export LD_LIBRARY_PATH="$here/lib${LD_LIBRARY_PATH:+:$LD_LIBRARY_PATH}"
[ -d "$here/layers" ] && export VK_LAYER_PATH="$here/layers"
export DRR_SHADER_DIR="$here/shaders"
if [ "${DRR_ARENA:-small}" = large ]; then
  export DRR_MEDIA_DIR="$here/Media/large"
else
  export DRR_MEDIA_DIR="$here/Media"
fi
export DRR_BENCH_SHADER_DIR="$here/bench-shaders"
exec "$here/bin/${DRR_BIN:-DynamicResolutionRendering}" "$@"
RUN
chmod +x "$out/run.sh"

# A run on a GPU machine carries the repository's tracked files and the bundle
# together, at most 64 MiB: say so here rather than there.
bundle_bytes=$(du -sb "$out" | cut -f1)
tree_bytes=$(cd "$root" && git ls-files -z | xargs -0 stat -c %s | awk '{n += $1} END {print n + 0}')
mib() { awk -v b="$1" 'BEGIN {printf "%.1f MiB", b / 1048576}'; }
echo "bundle $(mib "$bundle_bytes"), with the tracked files $(mib $((bundle_bytes + tree_bytes)))"
if ((bundle_bytes + tree_bytes > 64 * 1048576)); then
  echo "make-bundle: the bundle and the tracked files exceed the 64 MiB a GPU machine's run carries" >&2
  ((from_build)) || exit 1  # a --from-build bundle checks the layout only
fi
