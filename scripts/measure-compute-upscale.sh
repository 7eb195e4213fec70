#!/usr/bin/env bash
# The upscale pass's GPU time on this machine's Vulkan device: point against
# TAAU with pixel shaders and with compute shaders (Docs/Results.md, "The
# upscalers as compute passes"), in interleaved rounds. The compute TAAU runs
# twice: as the sample runs it at these scales (taau-compute: the 3x3
# neighbourhoods from a group-shared tile) and as its version without the
# tile (taau-direct: the build's UpscaleTemporal_TemporalUpsampleDirectCS in
# its place), which reads them from the textures. taau-fast-pixel and
# taau-fast-compute are TAAU's faster permutation (--filter taau-fast: a cross
# neighbourhood and a bilinear history). Each run renders
# FRAMES frames of camera 1 at WIDTHxHEIGHT and scale SCALE with the animation
# time frozen; the first WARM frames are dropped. Per round, the median of the
# scale pass's timer per configuration and its ratio to point's median of the
# same round (rounds.csv); the table (table.md) gives the median over rounds of
# both, and the lowest and highest ratio.
#   measure-compute-upscale.sh [--decompose] [rounds (default 5)] [output dir]
# --decompose adds three compute shaders that are not part of the sample
# (scripts/compute-upscale-variants/), built here with the build's own
# glslang command, which take the direct TAAU's cost apart: without the
# neighbourhood's texel reads, without those and the history's reads, and one
# texel read only.
# Environment: BUILD_DIR (default build), WIDTH, HEIGHT, SCALE, FRAMES, WARM;
# EXTRA="name=file.hlsl ..." adds compute TAAU shaders built from those files
# (another commit's UpscaleTemporalCS.hlsl, for one: a before/after in the
# same rounds); BASELINE_BUILD=dir adds another build's compute TAAU and
# point (baseline-taau-compute, baseline-point: its sample and its shaders,
# for a change outside the shader). ONLY="name ..." runs only those
# configurations (and point, the reference of every ratio).
set -euo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
build="${BUILD_DIR:-$root/build}"
sample="$build/DynamicResolutionRendering/DynamicResolutionRendering"
decompose=0
if [ "${1:-}" = --decompose ]; then decompose=1; shift; fi
rounds="${1:-5}"
out="${2:-$(mktemp -d)}"
out="$(mkdir -p "$out" && cd "$out" && pwd)"  # absolute: the build command runs in another folder
width="${WIDTH:-640}" height="${HEIGHT:-360}" scale="${SCALE:-0.71}" frames="${FRAMES:-36}" warm="${WARM:-12}"
mkdir -p "$out/reports"
# name | sample arguments | compute shader replacing UpscaleTemporalCS.hlsl's (variants only)
# | another build (baselines only)
configs=("point|--filter point|" "taau-pixel|--filter taau --upscale-shader pixel|"
         "taau-compute|--filter taau --upscale-shader compute|"
         "taau-direct|--filter taau --upscale-shader compute|UpscaleTemporal_TemporalUpsampleDirectCS.spv"
         "taau-fast-pixel|--filter taau-fast --upscale-shader pixel|"
         "taau-fast-compute|--filter taau-fast --upscale-shader compute|")
if ((decompose)); then
  configs+=("no-neighbourhood|--filter taau --upscale-shader compute|TemporalNoNeighbourhoodCS.hlsl"
            "no-history|--filter taau --upscale-shader compute|TemporalNoHistoryCS.hlsl"
            "one-texel|--filter taau --upscale-shader compute|TemporalOneTexelCS.hlsl")
fi
if [ -n "${BASELINE_BUILD:-}" ]; then
  baseline="$(cd "$BASELINE_BUILD" && pwd)"
  configs+=("baseline-point|--filter point||$baseline"
            "baseline-taau-compute|--filter taau --upscale-shader compute||$baseline")
fi
for e in ${EXTRA:-}; do configs+=("${e%%=*}|--filter taau --upscale-shader compute|$(realpath "${e#*=}")"); done
if [ -n "${ONLY:-}" ]; then
  kept=()
  for c in "${configs[@]}"; do
    [[ " point $ONLY " = *" ${c%%|*} "* ]] && kept+=("$c")
  done
  configs=("${kept[@]}")
fi

# A copy of the build's shaders with the compute TAAU replaced by a variant:
# another of the build's shaders (.spv) or one built here (.hlsl).
spv=UpscaleTemporal_TemporalUpsampleCS.spv
shader_dir() {
  local variant="$1" dir
  dir="$out/shaders-$(basename "${1%.*}")"
  [ -z "$variant" ] && { echo "$build/shaders"; return; }
  if [ ! -f "$dir/$spv" ]; then
    mkdir -p "$dir" && cp "$build/shaders/"*.spv "$dir/"
    if [ "${variant##*.}" = spv ]; then
      cp "$build/shaders/$variant" "$dir/$spv"
    else
      local cmd src="$variant"
      [[ $src = /* ]] || src="$root/scripts/compute-upscale-variants/$variant"
      cmd="$(ninja -C "$build" -t commands "shaders/$spv" | tail -n 1)"
      cmd="${cmd//$root\/Shaders\/UpscaleTemporalCS.hlsl/$src}"
      cmd="${cmd//$build\/shaders\/$spv/$dir/$spv}"
      (eval "$cmd -I$root/Shaders") >/dev/null
    fi
  fi
  echo "$dir"
}

for ((r = 1; r <= rounds; ++r)); do
  for c in "${configs[@]}"; do
    IFS='|' read -r name args variant other <<<"$c"
    read -r -a argv <<<"$args"
    run_sample="$sample" shaders="$(shader_dir "$variant")"
    [ -n "$other" ] && run_sample="$other/DynamicResolutionRendering/DynamicResolutionRendering" shaders="$other/shaders"
    DRR_SHADER_DIR="$shaders" "$run_sample" --headless --width "$width" --height "$height" \
      --frames "$frames" --time 3 --scale "$scale" --camera 1 --no-gui --quiet "${argv[@]}" \
      --report "$out/reports/$name-$r.json" 2>/dev/null >/dev/null
  done
done

names=()
for c in "${configs[@]}"; do names+=("${c%%|*}"); done
python3 - "$out" "$warm" "$rounds" "$width x $height, scale $scale, $frames frames a run ($warm dropped)" \
  "${names[@]}" <<'PY' | tee "$out/table.md"
import json, statistics, sys
out, warm, rounds, what, names = sys.argv[1], int(sys.argv[2]), int(sys.argv[3]), sys.argv[4], sys.argv[5:]
def round_median(name, r):
    frames = json.load(open(f"{out}/reports/{name}-{r}.json"))["frames"]
    return statistics.median(f["gpu_ms"]["scale"] for f in frames[warm:] if f.get("gpu_new"))
med = {n: [round_median(n, r) for r in range(1, rounds + 1)] for n in names}
with open(f"{out}/rounds.csv", "w") as csv:
    csv.write("round," + ",".join(names) + "\n")
    for r in range(rounds):
        csv.write(f"{r + 1}," + ",".join(f"{med[n][r]:.4f}" for n in names) + "\n")
print(f"{what}; {rounds} interleaved rounds\n")
print("| configuration | scale pass, median ms | x point, median | x point, lowest..highest |")
print("| --- | ---: | ---: | ---: |")
for n in names:
    ratios = [a / p for a, p in zip(med[n], med["point"])]
    print(f"| {n} | {statistics.median(med[n]):.2f} | {statistics.median(ratios):.2f} | "
          f"{min(ratios):.2f}..{max(ratios):.2f} |")
PY
