#!/usr/bin/env bash
# Controller at 3840x2160, large Arena: measure t(s) at fixed scales, then the
# laws with the budget at half the native frame; the settled scale should sit
# where the measured t(s) crosses the budget.
set -u
for f in .gl/*.deb; do dpkg -x "$f" / ; done; ldconfig
B=$PWD/.devcarry/bundle
exec > >(tee -a "$OUT/log.txt") 2>&1
NVEGL=$(ldconfig -p | awk '/libEGL_nvidia.so.0/ {print $NF; exit}')
printf '{"file_format_version":"1.0.0","ICD":{"library_path":"%s","api_version":"1.3.0"}}\n' "$NVEGL" >/tmp/nv_icd.json
export VK_DRIVER_FILES=/tmp/nv_icd.json VK_ICD_FILENAMES=/tmp/nv_icd.json
export DRR_ARENA=large
W="--width 3840 --height 2160 --no-gui"
med() { python3 - "$1" <<'PY'
import json, sys, statistics as s
r=json.load(open(sys.argv[1])); f=[x for x in r['frames'][-60:] if x.get('gpu_new')]
print("%.3f" % s.median(x['gpu_ms']['frame'] for x in f))
PY
}
$B/run.sh --headless $W --frames 120 --no-dynamic-resolution --report /tmp/native.json >/dev/null 2>&1
NATIVE=$(med /tmp/native.json); echo "native (dynamic resolution off) gpu frame $NATIVE ms"
for s in 0.3 0.4 0.5 0.55 0.6 0.65 0.71 0.8 0.9 1.0; do
  $B/run.sh --headless $W --frames 120 --scale $s --report /tmp/r.json >/dev/null 2>&1; echo "fixed scale $s: gpu frame $(med /tmp/r.json) ms"
done
HZ=$(python3 -c "print(round(2000.0/$NATIVE,3))"); echo "budget $(python3 -c "print($NATIVE/2)") ms -> --refresh $HZ"
for law in article robust ue-style; do
  $B/run.sh --headless $W --frames 600 --control vsync --refresh $HZ --law $law --report /tmp/ctl.json >/dev/null 2>&1
  python3 - $law <<'PY'
import json, sys, statistics as s
law=sys.argv[1]; r=json.load(open('/tmp/ctl.json')); f=r['frames']
sc=[x['scale'][0] for x in f]; new=[x for x in f[-200:] if x.get('gpu_new')]
ch=sum(1 for a,b in zip(sc[-200:],sc[-199:]) if a!=b)
print(f"{law}: last-200 median scale {s.median(sc[-200:]):.3f} range {min(sc[-200:]):.3f}-{max(sc[-200:]):.3f}, changes {ch}, median GPU frame {s.median(x['gpu_ms']['frame'] for x in new):.2f} ms")
PY
done
