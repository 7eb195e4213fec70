#!/usr/bin/env python3
"""Measures what one --fix changes: the same frame rendered with the original's
default and with the fix, compared pixel by pixel, and the GPU pass times of
both (median over the frames after the first half, runs interleaved).

  scripts/measure-fix.py NAME [sample options...]
  scripts/measure-fix.py uv-inset --filter bilinear --scale 0.5

Default sample options: --headless --width 640 --height 360 --no-gui --frames 60
--time 3 --control manual. Options after NAME are appended (later ones win).
Prints one Markdown table row: fix | options | pixels changed | largest channel
difference | PSNR of fix vs default | median GPU ms per pass, default -> fix."""
import json, os, statistics, subprocess, sys, tempfile

HERE = os.path.dirname(os.path.abspath(__file__))
BINARY = os.environ.get("DRR_BINARY", os.path.join(HERE, "..", "build", "DynamicResolutionRendering",
                                                   "DynamicResolutionRendering"))
BASE = ["--headless", "--width", "640", "--height", "360", "--no-gui", "--frames", "60", "--time", "3",
        "--control", "manual"]


def render(args, out_dir, tag):
    png = os.path.join(out_dir, tag + ".png")
    report = os.path.join(out_dir, tag + ".json")
    subprocess.run([BINARY] + args + ["--screenshot", png, "--report", report], check=True,
                   stdout=subprocess.DEVNULL)
    with open(report) as f:
        return png, json.load(f)


def compare(a, b):
    """(changed pixels, largest channel difference 0..255, PSNR dB) from idiff."""
    r = subprocess.run(["idiff", a, b], capture_output=True, text=True)
    text = r.stdout + r.stderr
    changed, maxerr, psnr = 0, 0.0, float("inf")
    for line in text.splitlines():
        line = line.strip()
        if line.startswith("Peak SNR"):
            psnr = float(line.split("=")[1])
        elif line.startswith("Max error"):
            maxerr = float(line.split("=")[1].split()[0]) * 255.0
        elif "pixels" in line and "over" in line:
            changed = int(line.split()[0])
    return changed, maxerr, psnr


def medians(report):
    frames = [f for f in report["frames"] if f.get("rendered")]
    keep = frames[len(frames) // 2:]
    out = {}
    for key in keep[0]["gpu_ms"]:
        out[key] = statistics.median(f["gpu_ms"][key] for f in keep)
    return out


def main():
    if len(sys.argv) < 2 or sys.argv[1] in ("-h", "--help"):
        print(__doc__)
        return 0 if len(sys.argv) >= 2 else 2
    fix, extra = sys.argv[1], sys.argv[2:]
    with tempfile.TemporaryDirectory() as d:
        runs = {"default": [], "fix": []}
        for rep in range(2):  # interleaved: default, fix, default, fix
            runs["default"].append(render(BASE + extra, d, f"default{rep}"))
            runs["fix"].append(render(BASE + extra + ["--fix", fix], d, f"fix{rep}"))
        same, _, _ = compare(runs["default"][0][0], runs["default"][1][0])
        changed, maxerr, psnr = compare(runs["default"][0][0], runs["fix"][0][0])
        w, h = runs["default"][0][1]["back_buffer"]
        times = {k: [medians(report) for _, report in v] for k, v in runs.items()}
        parts = []
        for key in times["default"][0]:
            a = statistics.mean(t[key] for t in times["default"])
            b = statistics.mean(t[key] for t in times["fix"])
            parts.append(f"{key} {a:.3f} -> {b:.3f}")
        note = "" if same == 0 else f" (default vs itself: {same} px differ)"
        print(f"| {fix} | {' '.join(extra) or '(defaults)'} | {changed} of {w * h}{note} | "
              f"{maxerr:.0f}/255 | {psnr:.2f} dB | {'; '.join(parts)} |")
    return 0


if __name__ == "__main__":
    sys.exit(main())
