#!/usr/bin/env bash
# corrupt-models.sh <drr_model_probe> [count] [models dir]
# Makes `count` corrupted copies (half truncated, half byte-flipped, chosen
# deterministically) of the model files of Debian's assimp-testmodels and
# loads each through the probe (so through the import worker) with
# Tests/scene/run_testmodels.sh: exits non-zero on any crash or hang.
# Not part of CI's time; used for the reliability counts in Docs/Reliability.md.
# DRR_PROBE_ARGS=--in-process measures the loaders without the isolation (before).
set -euo pipefail
probe=$1; count=${2:-300}; src=${3:-/usr/share/assimp/models}
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
out=$(mktemp -d /tmp/drr_corrupt.XXXXXX)
trap 'rm -rf "$out"' EXIT
mapfile -t exts < <("$probe" --list-extensions | sed -n 's/^\*\.//p' | tr 'A-Z' 'a-z' | sort -u)
python3 - "$src" "$out" "$count" "${exts[@]}" <<'PY'
import os, random, sys
src, out, count, exts = sys.argv[1], sys.argv[2], int(sys.argv[3]), set(sys.argv[4:])
files = sorted(os.path.join(d, f) for d, _, fs in os.walk(src) for f in fs
               if '.' in f and f.rsplit('.', 1)[1].lower() in exts and os.path.getsize(os.path.join(d, f)) > 0)
rng = random.Random(20110301)
for i in range(count):
    f = files[rng.randrange(len(files))]
    data = bytearray(open(f, 'rb').read())
    if i % 2 == 0:
        data = data[:rng.randrange(1, len(data))] if len(data) > 1 else data
        kind = 'trunc'
    else:
        for _ in range(rng.randint(1, 16)):
            data[rng.randrange(len(data))] ^= 1 << rng.randrange(8)
        kind = 'flip'
    name = f"{i:04d}_{kind}_{os.path.basename(f)}"
    open(os.path.join(out, name), 'wb').write(data)
print(f"{count} corrupted copies of {len(files)} files in {out}")
PY
bash "$root/Tests/scene/run_testmodels.sh" "$probe" "$out" 0 1 "${CORRUPT_LOG:-/tmp/drr_corrupt.log}"
