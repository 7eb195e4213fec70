#!/usr/bin/env python3
"""The tables of the OpenGL ES 2.0 article's claims (Docs/GLES2.md), from committed data.

Reads DIR/results.json of scripts/measure-gles2.sh (the bench with --preset gles2:
bilinear at 1.0, 0.75, 0.625, 0.5 and 0.25 and native, still views and the moving
cinematic camera) and prints two tables; with --write DOC it replaces them between
the markers <!-- gles2-tables:begin --> and <!-- gles2-tables:end --> in DOC; with
--check DOC it exits 1 when DOC's tables are not the ones the data gives.

1. Overhead of the render-target path at 1.0: bilinear 1.0 (scene into the native-size
   target, full-screen quad to the back buffer) against native (the scene straight into
   the back buffer), GPU frame time of each interleaved timing round (median of the
   round's frames; rounds rotate the order). Difference paired per round, mean +- 95 %
   t interval over the rounds. A time verdict only where the interval excludes 0 and
   the effect is larger than the spread of native's own rounds (largest - smallest).
   Beside it the quad pass's own GPU time (its timestamp queries), mean +- t over rounds.
2. Image error at each factor: PSNR and FLIP against the 4x4 super-sampled reference.
   Still: paired per view (native - bilinear f in PSNR, bilinear f - native in FLIP),
   t over views. Moving: paired per frame, the differences averaged in 6 blocks of
   consecutive frames, t over blocks. "Acceptable" is a loss of at most 1 dB PSNR and
   at most 0.02 FLIP against native: "acceptable" where both intervals lie wholly
   below their thresholds, "not acceptable" where both lie wholly above, "cannot
   decide" otherwise (an interval spans its threshold, or the metrics disagree).

Usage: scripts/gles2-tables.py DIR[,OVERHEAD_DIR...] [--write|--check Docs/GLES2.md]
(further folders: runs of the overhead alone, one overhead table each)
"""
import json
import math
import os
import statistics as st
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import doc_tables  # noqa: E402

FACTORS = [1.0, 0.75, 0.625, 0.5, 0.25]
PSNR_LOSS_DB, FLIP_GAIN = 1.0, 0.02
BLOCKS = 6
BEGIN, END = "<!-- gles2-tables:begin -->", "<!-- gles2-tables:end -->"
# Two-sided 95 % quantiles of Student's t, degrees of freedom 1..30.
T95 = [12.706, 4.303, 3.182, 2.776, 2.571, 2.447, 2.365, 2.306, 2.262, 2.228, 2.201, 2.179, 2.160, 2.145,
       2.131, 2.120, 2.110, 2.101, 2.093, 2.086, 2.080, 2.074, 2.069, 2.064, 2.060, 2.056, 2.052, 2.048,
       2.045, 2.042]


def mean_ci(values):
    """Mean and 95 % half-width (t) of independent values; half-width NaN for fewer than 2."""
    values = [v for v in values if v is not None and math.isfinite(v)]
    if not values:
        return math.nan, math.nan
    if len(values) < 2:
        return values[0], math.nan
    t = T95[min(len(values) - 1, len(T95)) - 1]
    return st.mean(values), t * st.stdev(values) / math.sqrt(len(values))


def blocks(diffs, n=BLOCKS):
    """Means of n blocks of consecutive values (neighbouring frames are correlated)."""
    size = len(diffs) // n
    return [st.mean(diffs[i * size:(i + 1) * size]) for i in range(n)] if size else []


def side(mean, half, threshold):
    """+1: the interval lies above threshold, -1 below, 0 spans it (or is unknown)."""
    if not (math.isfinite(mean) and math.isfinite(half)):
        return 0
    return 1 if mean - half > threshold else -1 if mean + half < threshold else 0


def pm(mean, half, digits):
    return f"{mean:+.{digits}f} ± {half:.{digits}f}" if math.isfinite(half) else f"{mean:+.{digits}f} ± ?"


def load(folder):
    with open(os.path.join(folder, "results.json")) as f:
        run = json.load(f)
    rows = {}
    for r in run["rows"]:
        rows[(r["view"], r["filter"], round(float(r["scale"]), 3), bool(r["moving"]))] = r
    return run, rows


def views(rows, moving):
    return sorted({k[0] for k in rows if k[3] == moving and k[1] == "native"})


def frame_ms(row):
    return row.get("gpu_ms", {}).get("frame", {}).get("median")


def quad_cell(row):
    """The full-screen quad's own GPU time: mean +- t interval over the rounds' medians."""
    mean, half = mean_ci(row.get("per_round", {}).get("gpu_scale_ms", []))
    return f"{mean:.2f} ± {half:.2f}" if math.isfinite(half) else "-"


def overhead_table(rows):
    lines = ["| view | native ms (straight to the back buffer) | bilinear 1.0 ms (target + quad) | "
             "paired difference ms | % of native | rounds | native's spread over rounds ms | verdict | "
             "quad pass ms (own timestamps) |",
             "| --- | ---: | ---: | ---: | ---: | ---: | ---: | --- | ---: |"]
    for moving in (False, True):
        for view in views(rows, moving):
            nat, bil = rows.get((view, "native", 1.0, moving)), rows.get((view, "bilinear", 1.0, moving))
            if not nat or not bil:
                continue
            a = nat.get("per_round", {}).get("gpu_frame_ms", [])
            b = bil.get("per_round", {}).get("gpu_frame_ms", [])
            if not a or not b:
                continue  # not timed (an interrupted run)
            d = [y - x for x, y in zip(a, b)]
            mean, half = mean_ci(d)
            spread, base = max(a) - min(a), st.mean(a)
            s = side(mean, half, 0.0)
            if s == 0 or not abs(mean) > spread:
                verdict = "cannot decide" + (" (interval spans 0)" if s == 0 else " (effect within native's spread)")
            else:
                verdict = "render-target path dearer" if s > 0 else "render-target path cheaper"
            lines.append(f"| {view} | {st.median(a):.2f} | {st.median(b):.2f} | {pm(mean, half, 2)} | "
                         f"{100 * mean / base:+.1f} % ± {100 * half / base:.1f} | {len(d)} | {spread:.2f} | {verdict} | "
                         f"{quad_cell(bil)} |")
    return "\n".join(lines) + "\n"


def still_differences(rows, factor, key):
    """Per still view: bilinear f minus native of the metric."""
    out = []
    for view in views(rows, False):
        nat, bil = rows.get((view, "native", 1.0, False)), rows.get((view, "bilinear", factor, False))
        if nat and bil and nat.get(key) is not None and bil.get(key) is not None:
            out.append(bil[key] - nat[key])
    return out


def moving_differences(rows, factor, key):
    """Per block of frames of the moving camera: bilinear f minus native."""
    out = []
    for view in views(rows, True):
        nat, bil = rows.get((view, "native", 1.0, True)), rows.get((view, "bilinear", factor, True))
        if not nat or not bil:
            continue
        a, b = nat.get("per_frame", {}).get(key, []), bil.get("per_frame", {}).get(key, [])
        out += blocks([y - x for x, y in zip(a, b) if x is not None and y is not None])
    return out


def verdict(psnr_loss, flip_gain):
    p, f = side(*psnr_loss, PSNR_LOSS_DB), side(*flip_gain, FLIP_GAIN)
    if p < 0 and f < 0:
        return "acceptable"
    if p > 0 and f > 0:
        return "not acceptable"
    return "cannot decide" + (" (an interval spans its threshold)" if p == 0 or f == 0 else " (metrics disagree)")


def error_table(rows):
    lines = ["| factor | viewport | camera | PSNR dB (mean) | PSNR loss vs native dB | FLIP (mean) | "
             "FLIP gain vs native | n | verdict |",
             "| ---: | ---: | --- | ---: | ---: | ---: | ---: | ---: | --- |"]
    for factor in FACTORS:
        for moving, differences, unit in ((False, still_differences, "views"), (True, moving_differences, "blocks")):
            got = [r for k, r in rows.items() if k[1] == "bilinear" and k[2] == factor and k[3] == moving]
            nat = [r for k, r in rows.items() if k[1] == "native" and k[3] == moving]
            if not got or not nat:
                continue
            key = "psnr_db"
            loss = mean_ci([-d for d in differences(rows, factor, key)])
            gain = mean_ci(differences(rows, factor, "flip"))
            n = len(differences(rows, factor, key))
            psnr = st.mean(r[key] for r in got)
            flip = st.mean(r["flip"] for r in got)
            vp = got[0].get("viewport", [0, 0])
            lines.append(f"| {factor:g} | {int(vp[0])}x{int(vp[1])} | {'moving x1' if moving else 'still'} | "
                         f"{psnr:.2f} | {pm(*loss, 2)} | {flip:.4f} | {pm(*gain, 4)} | {n} {unit} | "
                         f"{verdict(loss, gain)} |")
    for moving in (False, True):
        nat = [r for k, r in rows.items() if k[1] == "native" and k[3] == moving]
        if nat:
            lines.append(f"| native | full | {'moving x1' if moving else 'still'} | "
                         f"{st.mean(r['psnr_db'] for r in nat):.2f} | - | "
                         f"{st.mean(r['flip'] for r in nat):.4f} | - | - | - |")
    return "\n".join(lines) + "\n"


def head(folder, run):
    return (f"Data: `{folder}/results.json` ({run.get('driver', '?')}, {run.get('width')}x{run.get('height')}, "
            f"FLIP at {run.get('flip_ppd')} ppd, {run.get('validation_messages')} validation messages, "
            f"complete: {run.get('complete')}).\n\n")


def tables(arg):
    """The first folder's overhead and error tables, then the overhead table of each further one."""
    folders = arg.split(",")
    run, rows = load(folders[0])
    text = head(folders[0], run) + overhead_table(rows) + "\n" + error_table(rows)
    for folder in folders[1:]:
        run, rows = load(folder)
        text += "\n" + head(folder, run) + overhead_table(rows)
    return text


if __name__ == "__main__":
    sys.exit(doc_tables.main(sys.argv, __doc__, tables, BEGIN, END, "gles2-tables"))
