#!/usr/bin/env python3
"""Figures for scripts/device-checks.sh from the sample's JSON reports, the
board-power samples and PNG frames. Standard library only (GPU machines have
python3 but not numpy).

  device-report.py frame-row REPORT WARMUP_MS     one run's per-pass GPU medians
  device-report.py frame-summary FRAME_CSV        medians over rounds, ratios
  device-report.py paced REPORT [POWER_CSV]       frame interval (and power) of a paced run
  device-report.py psnr A.png B.png               PSNR (dB) of two 8-bit PNGs
  device-report.py adapter REPORT                 the Vulkan adapter and driver that ran
"""
import csv
import json
import math
import statistics
import struct
import sys
import zlib

PASSES = ("frame", "scene", "postp", "scale")


def measured_frames(report, warmup_ms):
    """The frames after the first warmup_ms of real time that carry a new GPU result."""
    frames = [f for f in report["frames"] if f.get("rendered", True)]
    elapsed, kept = 0.0, []
    for f in frames:
        elapsed += f.get("cpu_ms", 0.0)
        if elapsed >= warmup_ms and f.get("gpu_new"):
            kept.append(f)
    return kept or [f for f in frames[len(frames) // 2:] if f.get("gpu_new")]


def frame_row(path, warmup_ms):
    report = json.load(open(path))
    kept = measured_frames(report, float(warmup_ms))
    cells = [str(len(kept))]
    for p in PASSES:
        values = [f["gpu_ms"][p] for f in kept]
        cells.append("%.4f" % statistics.median(values) if values else "nan")
    print(",".join(cells))


def spread(values):
    return "%.3f (%.3f-%.3f)" % (statistics.median(values), min(values), max(values))


def frame_summary(path):
    rows = list(csv.DictReader(open(path)))
    groups = {}
    for r in rows:
        if r["frame_ms"] in ("nan", ""):
            continue
        groups.setdefault((r["size"], r["arena"], r["config"]), []).append(r)
    print("| size | arena | config | runs | frame ms median (min-max) | scene | post | upscale pass | frame / native | pass / point's |")
    print("| --- | --- | --- | ---: | --- | --- | --- | --- | ---: | ---: |")
    for (size, arena, config), rs in sorted(groups.items()):
        med = {p: statistics.median(float(r[p + "_ms"]) for r in rs) for p in PASSES}
        native = groups.get((size, arena, "native"))
        ratio = "-"
        if native and config != "native":
            ratio = "%.3f" % (med["frame"] / statistics.median(float(r["frame_ms"]) for r in native))
        scale = config.rsplit("-", 1)[-1]
        point = groups.get((size, arena, "point-" + scale))
        pass_ratio = "-"
        if point and config.startswith("taau"):
            point_pass = statistics.median(float(r["scale_ms"]) for r in point)
            pass_ratio = "%.2f" % (med["scale"] / point_pass) if point_pass > 0 else "-"
        print("| %s | %s | %s | %d | %s | %.3f | %.3f | %.3f | %s | %s |" % (
            size, arena, config, len(rs), spread([float(r["frame_ms"]) for r in rs]), med["scene"], med["postp"],
            med["scale"], ratio, pass_ratio))


def paced(report_path, power_path=None):
    report = json.load(open(report_path))
    frames = [f for f in report["frames"] if f.get("rendered", True)][1:]
    intervals = sorted(f["cpu_ms"] for f in frames)
    scales = [f["scale"][0] for f in frames]
    tail = scales[len(scales) // 2:]
    q = lambda v, p: v[min(len(v) - 1, int(p * len(v)))]
    line = "frames %d, interval median %.3f ms (p10 %.3f, p90 %.3f), last half's scale %.3f-%.3f" % (
        len(intervals), statistics.median(intervals), q(intervals, 0.1), q(intervals, 0.9), min(tail), max(tail))
    if power_path:
        watts = []
        for row in open(power_path):
            try:
                watts.append(float(row.strip().split()[0]))
            except (ValueError, IndexError):
                pass
        watts = watts[10:] or watts  # the first second: loading
        if watts:
            watts.sort()
            line += ", board power median %.1f W (p10 %.1f, p90 %.1f, %d samples)" % (
                statistics.median(watts), q(watts, 0.1), q(watts, 0.9), len(watts))
    print(line)


def read_png(path):
    """Width, height, channels and the rows of an 8-bit, non-interlaced PNG."""
    data = open(path, "rb").read()
    if data[:8] != b"\x89PNG\r\n\x1a\n":
        raise ValueError(path + ": not a PNG")
    pos, idat, header = 8, b"", None
    while pos < len(data):
        length, kind = struct.unpack(">I4s", data[pos:pos + 8])
        body = data[pos + 8:pos + 8 + length]
        if kind == b"IHDR":
            header = struct.unpack(">IIBBBBB", body)
        elif kind == b"IDAT":
            idat += body
        pos += 12 + length
    w, h, depth, colour, _, _, interlace = header
    channels = {0: 1, 2: 3, 4: 2, 6: 4}.get(colour)
    if depth != 8 or channels is None or interlace:
        raise ValueError("%s: only 8-bit non-interlaced grey/RGB/RGBA PNGs" % path)
    raw, stride, rows, prev = zlib.decompress(idat), w * channels, [], bytearray(w * channels)
    for y in range(h):
        kind, line = raw[y * (stride + 1)], bytearray(raw[y * (stride + 1) + 1:(y + 1) * (stride + 1)])
        for i in range(stride):
            a = line[i - channels] if i >= channels else 0
            b, c = prev[i], prev[i - channels] if i >= channels else 0
            if kind == 1:
                line[i] = (line[i] + a) & 255
            elif kind == 2:
                line[i] = (line[i] + b) & 255
            elif kind == 3:
                line[i] = (line[i] + (a + b) // 2) & 255
            elif kind == 4:
                pa, pb, pc = abs(b - c), abs(a - c), abs(a + b - 2 * c)
                line[i] = (line[i] + (a if pa <= pb and pa <= pc else b if pb <= pc else c)) & 255
        rows.append(line)
        prev = line
    return w, h, channels, rows


def psnr(a_path, b_path):
    wa, ha, ca, a = read_png(a_path)
    wb, hb, cb, b = read_png(b_path)
    if (wa, ha) != (wb, hb):
        print("size differs: %dx%d against %dx%d" % (wa, ha, wb, hb))
        return 1
    total, n = 0, 0
    for ra, rb in zip(a, b):
        for x in range(wa):
            for k in range(3):
                d = ra[x * ca + min(k, ca - 1)] - rb[x * cb + min(k, cb - 1)]
                total += d * d
            n += 3
    mse = total / n
    print("inf" if mse == 0 else "%.2f" % (10 * math.log10(255 * 255 / mse)))
    return 0


def adapter(path):
    report = json.load(open(path))
    print("adapter: %s, driver %s" % (report.get("adapter", "?"), report.get("driver", "?")))


def main(argv):
    if len(argv) >= 3 and argv[1] == "frame-row":
        return frame_row(argv[2], argv[3] if len(argv) > 3 else 0) or 0
    if len(argv) == 3 and argv[1] == "frame-summary":
        return frame_summary(argv[2]) or 0
    if len(argv) in (3, 4) and argv[1] == "paced":
        return paced(*argv[2:]) or 0
    if len(argv) == 3 and argv[1] == "adapter":
        return adapter(argv[2]) or 0
    if len(argv) == 4 and argv[1] == "psnr":
        return psnr(argv[2], argv[3])
    sys.stderr.write(__doc__)
    return 2


if __name__ == "__main__":
    sys.exit(main(sys.argv))
