#!/usr/bin/env bash
# reliability_cli.sh <sample> <case> <scratch dir>
# One reliability check of the sample's command line per case; prints what it
# saw and exits non-zero when the sample does not behave as required.
set -u
exe=$1; case_=$2; dir=$3
mkdir -p "$dir"
run() { "$exe" --headless --width 64 --height 64 --frames 2 "$@" > "$dir/out.txt" 2>&1; echo $? > "$dir/rc"; }
rc() { cat "$dir/rc"; }
has() { grep -q -- "$1" "$dir/out.txt" || { echo "missing '$1' in:"; cat "$dir/out.txt"; exit 1; }; }
hasnt() { ! grep -q -- "$1" "$dir/out.txt" || { echo "unexpected '$1' in:"; cat "$dir/out.txt"; exit 1; }; }
want_rc() { [[ $(rc) == "$1" ]] || { echo "exit code $(rc), expected $1"; cat "$dir/out.txt"; exit 1; }; }
nonzero() { [[ $(rc) != 0 ]] || { echo "exit code 0, expected a failure"; cat "$dir/out.txt"; exit 1; }; }
# A one-triangle model that references a texture that does not exist.
model() {
  printf 'mtllib tri.mtl\nv -50 -50 0\nv 50 -50 0\nv 0 50 0\nvt 0 0\nvt 1 0\nvt 0 1\nusemtl m\nf 1/1 2/2 3/3\n' > "$dir/tri.obj"
  printf 'newmtl m\nKd 1 1 1\nmap_Kd missing_texture.png\n' > "$dir/tri.mtl"
}
case $case_ in
  scene_long_component)
    long=$(printf 'a%.0s' $(seq 300))
    run --scene "$dir/$long/scene.txt"; want_rc 1; has "File name too long" ;;
  scene_symlink_loop)
    ln -sfn loop_b "$dir/loop_a"; ln -sfn loop_a "$dir/loop_b"
    run --scene "$dir/loop_a/scene.txt"; want_rc 1; has "symbolic links" ;;
  report_dev_full)
    run --report /dev/full; nonzero; has "report: cannot write /dev/full" ;;
  report_long_dev_full)
    "$exe" --headless --width 64 --height 64 --frames 400 --report /dev/full > "$dir/out.txt" 2>&1; echo $? > "$dir/rc"
    nonzero; has "report: cannot write /dev/full (disk full or write error)"; hasnt "report written" ;;
  screenshot_dev_full)
    ln -sfn /dev/full "$dir/full.png"
    run --screenshot "$dir/full.png"; nonzero; has "screenshot: .*full.png: write failed"; hasnt "screenshot written" ;;
  missing_texture_warns)
    model; run --scene "$dir/tri.obj"; want_rc 0; has "warning: scene: .*missing_texture.png" ;;
  missing_texture_quiet)
    model; run --scene "$dir/tri.obj" --quiet --stats --report "$dir/r.json"; want_rc 0
    hasnt "^warning:"; has "warnings: 1"
    python3 -c "import json,sys; w=json.load(open(sys.argv[1]))['warnings']; assert len(w)==1 and 'missing_texture.png' in w[0], w" "$dir/r.json" ;;
  absurd_transform_warns)
    model; printf 'tri.obj NO_ANIM LIT translate=3e38,0,0\ntri.obj NO_ANIM LIT scale=1e30\n' > "$dir/scene.txt"
    run --scene "$dir/scene.txt"; want_rc 0
    has "scene.txt:1: translate=3e+38,0,0 is beyond"; has "scene.txt:2: scale=1e+30,1e+30,1e+30 is outside" ;;
  scale_cut_warns)
    "$exe" --headless --width 5000 --height 64 --frames 2 --supersampling --scale 2 --report "$dir/r.json" > "$dir/out.txt" 2>&1
    echo $? > "$dir/rc"; want_rc 0; has "warning: scale 2 x 2 exceeds the 8192-pixel render-target limit"
    python3 -c "import json,sys; s=json.load(open(sys.argv[1]))['final_scale']; assert s[0]==s[1], s" "$dir/r.json" ;;
  headless_ignores_window_options)
    run --window-test; has "warning: --window-test is ignored without a window"
    run --fullscreen; has "warning: --fullscreen is ignored without a window" ;;
  clean_shutdown)
    # Frames with every pass that holds queries or copies, under validation:
    # the device is destroyed at exit and destroying it raises no message
    # (the layer reports undestroyed objects then).
    "$exe" --headless --width 96 --height 64 --frames 30 --validation --zoom --filter taa \
      --screenshot "$dir/s.png" --report "$dir/r.json" > "$dir/out.txt" 2>&1; echo $? > "$dir/rc"
    want_rc 0; hasnt "shutdown:"; hasnt "d3dl validation" ;;
  *) echo "unknown case $case_"; exit 2 ;;
esac
echo "ok: $case_"
