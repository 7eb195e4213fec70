#!/usr/bin/env bash
# run_testmodels.sh <drr_model_probe> <models dir> <shard> <shards> [log] [stride]
# Loads every model file (by the extensions Assimp imports) of the models
# folder that falls in this shard with drr_model_probe (with a stride N > 1,
# a fixed sample: the 1st, (N+1)-th, (2N+1)-th... file in name order), each in its own process
# under `timeout`, and classifies it: loaded (exit 0), clean failure (exit 1
# with an "error:" message), crash (killed by a signal or any other exit),
# hang (timeout). Exits non-zero if anything crashed or hung. The probe decodes
# through the import worker (IsolatedImport.h), whose limits are set below the
# script's, so a file that hangs Assimp is a clean failure; the log records the
# peak RSS of probe + worker per file (GNU time, when installed).
set -u
probe=$1; dir=$2; shard=${3:-0}; shards=${4:-1}; log=${5:-/dev/null}; stride=${6:-1}
limit=${DRR_PROBE_TIMEOUT:-60}
export DRR_IMPORT_CPU_SECONDS=${DRR_IMPORT_CPU_SECONDS:-10} DRR_IMPORT_TIMEOUT_SECONDS=${DRR_IMPORT_TIMEOUT_SECONDS:-20}
export DRR_IMPORT_MEMORY_MB=${DRR_IMPORT_MEMORY_MB:-4096}
timecmd=(); rssfile=$(mktemp); trap 'rm -f "$rssfile"' EXIT
[[ -x /usr/bin/time ]] && timecmd=(/usr/bin/time -q -f %M -o "$rssfile")
peak=0
mapfile -t exts < <("$probe" --list-extensions | sed -n 's/^\*\.//p' | tr 'A-Z' 'a-z' | sort -u)
declare -A ok_ext=()
for e in "${exts[@]}"; do ok_ext[$e]=1; done
mapfile -t files < <(find "$dir" -type f | LC_ALL=C sort)
loaded=0; failed=0; crashed=0; hung=0; n=0; idx=0
: > "$log"
start=$(date +%s)
for f in "${files[@]}"; do
  base=${f##*/}; ext=${base##*.}; ext=${ext,,}
  [[ "$base" == *.* && -n "${ok_ext[$ext]:-}" ]] || continue
  idx=$((idx + 1))
  (( (idx - 1) % stride == 0 )) || continue
  (( ((idx - 1) / stride) % shards == shard )) || continue
  n=$((n + 1))
  : > "$rssfile"
  out=$(timeout -k 5 "$limit" "${timecmd[@]}" "$probe" --quiet ${DRR_PROBE_ARGS:-} "$f" 2>&1); rc=$?
  rss=$(tail -n1 "$rssfile" 2>/dev/null); [[ "$rss" =~ ^[0-9]+$ ]] || rss=0
  (( rss > peak )) && peak=$rss
  echo "RSS_KB $rss $f" >> "$log"
  if (( rc == 0 )); then
    loaded=$((loaded + 1)); echo "LOADED  $f" >> "$log"
  elif (( rc == 124 || rc == 137 )); then
    hung=$((hung + 1)); echo "HANG    $f" | tee -a "$log"
  elif (( rc == 1 )) && grep -q '^error: ' <<<"$out"; then
    failed=$((failed + 1)); echo "FAILED  $f :: $(grep -m1 '^error: ' <<<"$out")" >> "$log"
  else
    crashed=$((crashed + 1)); echo "CRASH   $f (exit $rc) :: ${out: -300}" | tee -a "$log"
  fi
done
secs=$(( $(date +%s) - start ))
echo "assimp-testmodels shard $shard/$shards (every ${stride}. file): $n files: $loaded loaded, $failed clean failures, $crashed crashes, $hung hangs, peak RSS $((peak / 1024)) MiB (${secs}s, limit ${limit}s per file; log: $log)"
(( crashed == 0 && hung == 0 ))
