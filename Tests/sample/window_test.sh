#!/usr/bin/env bash
# Window test of the sample under Xvfb: the windowed image equals the headless
# one, and the app survives a 1x1 resize, minimise/restore and fullscreen
# toggles with zero validation messages (--validation: exit code 3 otherwise).
set -uo pipefail
exe="$1"
out="$2"
mkdir -p "$out"
common=(--width 320 --height 180 --time 1 --camera 1 --filter point --scale 0.71 --no-gui --validation)
fail=0

if [ -z "${DRR_IN_XVFB:-}" ]; then
  export DRR_IN_XVFB=1
  exec xvfb-run -a -s "-screen 0 1280x720x24" "$0" "$@"
fi

echo "== windowed vs headless image"
"$exe" "${common[@]}" --frames 6 --screenshot "$out/window.png" || { echo "windowed run failed ($?)"; fail=1; }
"$exe" --headless "${common[@]}" --frames 6 --screenshot "$out/headless.png" || { echo "headless run failed ($?)"; fail=1; }
if command -v idiff >/dev/null; then
  idiff -fail 0.004 -failpercent 0 "$out/window.png" "$out/headless.png"; rc=$?
  # idiff: 0 identical, 1 warning, 2 failure
  if [ $rc -ge 2 ]; then echo "images differ"; fail=1; else echo "images match (idiff rc $rc)"; fi
else
  cmp "$out/window.png" "$out/headless.png" && echo "images identical" || { echo "images differ"; fail=1; }
fi

echo "== scripted resize to 1x1, minimise, restore, fullscreen toggles"
"$exe" "${common[@]}" --frames 40 --window-test --screenshot "$out/after_events.png" --report "$out/events.json"
rc=$?
if [ $rc -ne 0 ]; then echo "window-test run failed with exit code $rc"; fail=1; else echo "window-test run ok"; fi

if command -v xdotool >/dev/null; then
  echo "== external resize with xdotool"
  "$exe" "${common[@]}" --frames 150 --report "$out/xdotool.json" &
  pid=$!
  for i in $(seq 1 50); do
    wid=$(xdotool search --name "Dynamic Resolution Rendering" 2>/dev/null | head -1)
    [ -n "$wid" ] && break
    sleep 0.1
  done
  if [ -n "${wid:-}" ]; then
    xdotool windowsize "$wid" 1 1; sleep 0.5
    xdotool windowsize "$wid" 500 300; sleep 0.5
    xdotool windowunmap "$wid"; sleep 0.5
    xdotool windowmap "$wid"; sleep 0.3
  else
    echo "window not found by xdotool"
  fi
  wait $pid; rc=$?
  if [ $rc -ne 0 ]; then echo "xdotool run failed with exit code $rc"; fail=1; else echo "xdotool run ok"; fi
fi
exit $fail
