#!/usr/bin/env python3
"""TAAU's two permutations, taau and taau-fast (Docs/Upscaling.md section 3), from committed data.

Reads the folder that the commands in its README.md wrote:
  timing/rounds.csv    scripts/measure-compute-upscale.sh: per interleaved round, the median
                       scale-pass time (ms) of point, taau-pixel, taau-compute,
                       taau-fast-pixel and taau-fast-compute
  quality/results.csv  the sample's --bench with --filters taau,taau-fast: PSNR and FLIP
                       against the 4x4 reference, still views and the moving camera
and prints the tables; --write DOC replaces them between <!-- taau-fast:begin --> and
<!-- taau-fast:end -->, --check DOC exits 1 when DOC's differ.

Usage: scripts/taau-fast-tables.py DIR [--write|--check Docs/Upscaling.md]
"""
import csv
import os
import random
import statistics as st
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import doc_tables  # noqa: E402

BEGIN, END = "<!-- taau-fast:begin -->", "<!-- taau-fast:end -->"
PASSES = ["point", "taau-pixel", "taau-fast-pixel", "taau-compute", "taau-fast-compute"]
PAIRS = [("pixel shaders", "taau-pixel", "taau-fast-pixel"), ("compute", "taau-compute", "taau-fast-compute")]


def rounds(folder):
    with open(os.path.join(folder, "timing", "rounds.csv")) as f:
        return [{k: float(v) for k, v in row.items()} for row in csv.DictReader(f)]


def bootstrap_median(values, n=2000, seed=1):
    """95 % percentile-bootstrap interval of the median (fixed seed: the table is reproducible)."""
    rng = random.Random(seed)
    meds = sorted(st.median(rng.choices(values, k=len(values))) for _ in range(n))
    return meds[int(0.025 * n)], meds[int(0.975 * n) - 1]


def timing_table(rows):
    out = [f"Scale pass at 0.71, {len(rows)} interleaved rounds (per round the median over the frames):", "",
           "| pass | median ms | x point: median (lowest..highest) |", "| --- | ---: | ---: |"]
    for name in PASSES:
        ratios = [r[name] / r["point"] for r in rows]
        out.append(f"| {name} | {st.median(r[name] for r in rows):.2f} | {st.median(ratios):.2f} "
                   f"({min(ratios):.2f}..{max(ratios):.2f}) |")
    out += ["", "| shaders | taau-fast / taau, paired per round: median [95 % bootstrap interval] | "
            "lowest..highest | rounds faster |", "| --- | ---: | ---: | ---: |"]
    for label, full, fast in PAIRS:
        ratios = [r[fast] / r[full] for r in rows]
        lo, hi = bootstrap_median(ratios)
        out.append(f"| {label} | {st.median(ratios):.3f} [{lo:.3f}, {hi:.3f}] | {min(ratios):.3f}..{max(ratios):.3f} | "
                   f"{sum(x < 1 for x in ratios)} of {len(ratios)} |")
    return "\n".join(out) + "\n"


def quality_rows(folder):
    with open(os.path.join(folder, "quality", "results.csv")) as f:
        return list(csv.DictReader(f))


def cell(row, moving):
    if row is None:
        return "-"
    text = f"{float(row['psnr_db']):.2f}"
    if moving and row["psnr_ci95"]:
        text += f" ± {float(row['psnr_ci95']):.2f}"
    text += f" / {float(row['flip']):.4f}"
    jitter = row["flicker_rms"] if moving else row["instability_rms"]
    if jitter:
        text += f" / {1000 * float(jitter):.1f}"
    return text


def quality_table(rows):
    views = list(dict.fromkeys(r["view"] for r in rows))
    find = {(r["view"], r["filter"], round(float(r["scale"]), 2)): r for r in rows}
    out = ["PSNR dB / FLIP / flicker x1000 (moving: frame-to-frame change of the error; still: change "
           "between consecutive frames, the jitter's shimmer):", "",
           "| view | native | taau 0.5 | taau-fast 0.5 | taau 0.71 | taau-fast 0.71 |",
           "| --- | ---: | ---: | ---: | ---: | ---: |"]
    for v in views:
        moving = "moving" in v
        native = find.get((v, "native", 1.0))
        cells = [cell(find.get((v, f, s)), moving) for s in (0.5, 0.71) for f in ("taau", "taau-fast")]
        out.append(f"| {v} | {cell(native, moving)} | " + " | ".join(cells) + " |")
    diffs = []
    for s in (0.5, 0.71):
        for v in views:
            full, fast = find.get((v, "taau", s)), find.get((v, "taau-fast", s))
            if full and fast:
                diffs.append(float(fast["psnr_db"]) - float(full["psnr_db"]))
    out += ["", f"taau-fast - taau, PSNR over the {len(diffs)} view and scale pairs: "
            f"{min(diffs):+.2f} to {max(diffs):+.2f} dB (median {st.median(diffs):+.2f})."]
    return "\n".join(out) + "\n"


def tables(folder):
    return timing_table(rounds(folder)) + "\n" + quality_table(quality_rows(folder))


if __name__ == "__main__":
    sys.exit(doc_tables.main(sys.argv, __doc__, tables, BEGIN, END, "taau-fast-tables"))
