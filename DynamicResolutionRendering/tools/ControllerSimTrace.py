#!/usr/bin/env python3
"""Turns the sample's --report JSON into a GPU-time trace for drr_controller_sim --trace.

Each frame record of the report carries the newest inner-frame GPU result and
its delay d in frames (the result polled at the top of frame F measured frame
F - d). The trace re-aligns every result with the frame it measured, so each
row pairs a GPU time with the scale that frame was rendered at:

    frame,scale,gpu_ms

Frames whose result never arrived (the last d frames, skipped measurements)
are left out. The header records the command, the adapter and the delay
histogram (the sample's real timer latency).
"""
import collections
import json
import sys


def main():
    if len(sys.argv) != 5:
        sys.exit("usage: ControllerSimTrace.py REPORT.json OUT.csv ROLE COMMAND")
    report_path, out_path, role, command = sys.argv[1:]
    with open(report_path) as f:
        report = json.load(f)
    frames = report["frames"]
    scale_of = {r["frame"]: r["scale"][0] for r in frames if r["rendered"]}
    delays = collections.Counter()
    rows = {}
    for r in frames:
        if not (r["rendered"] and r["gpu_new"]):
            continue
        d = r["gpu_delay_frames"]
        delays[d] += 1
        measured = r["frame"] - d
        if measured in scale_of:
            rows[measured] = (scale_of[measured], r["gpu_ms"]["frame"])
    with open(out_path, "w") as out:
        out.write(f"# {role}\n")
        out.write(f"# recorded by: {command}\n")
        out.write(f"# adapter: {report['adapter']}; back buffer {report['back_buffer'][0]}x{report['back_buffer'][1]}\n")
        hist = " ".join(f"{d}:{n}" for d, n in sorted(delays.items()))
        out.write(f"# timer delay in frames (result polled d frames after its frame), count: {hist}\n")
        out.write("frame,scale,gpu_ms\n")
        for n in sorted(rows):
            s, t = rows[n]
            out.write(f"{n},{s:.6f},{t:.4f}\n")


if __name__ == "__main__":
    main()
