#!/usr/bin/env python3
"""The error-against-time table of Docs/Deferred.md, generated from committed data.

Reads DIR/r<round>_<renderer>/results.csv of scripts/bench-renderers.sh (the quick
bench's TAA rows and native, per renderer, rounds one after the other) and prints the
table; with --write DOC it replaces the table between the markers
<!-- deferred-table:begin --> and <!-- deferred-table:end --> in DOC; with --check
DOC it exits 1 when DOC's table is not the one the data gives.

Cell: PSNR against the renderer's own reference (mean over rounds); GPU frame time
(median over rounds of each row's median); for the deferred columns the ratio of that
median to the forward one (so the two agree) and, in brackets, the range over rounds of
the same round's ratio. A ratio is marked "?" when the spread over rounds of either
column (largest / smallest of its medians) reaches the ratio's distance from 1:
repeated runs of one configuration differ by as much as the effect.

Usage: scripts/deferred-tables.py DIR [--write|--check Docs/Deferred.md]
"""
import csv
import glob
import os
import statistics as st
import sys

RENDERERS = ["forward", "deferred", "deferred-nossao", "deferred-lit"]
ROWS = [("taa", "0.300"), ("taa", "0.500"), ("taa", "0.710"), ("taa", "1.000"), ("native", "1.000")]
BEGIN, END = "<!-- deferred-table:begin -->", "<!-- deferred-table:end -->"


def still_rows(path):
    with open(path, newline="") as f:
        return {(r["filter"], r["scale"]): r for r in csv.DictReader(f) if r["moving"] == "0"}


def load(folder):
    runs = {}
    for renderer in RENDERERS:
        paths = sorted(glob.glob(os.path.join(folder, f"r*_{renderer}", "results.csv")))
        if not paths:
            sys.exit(f"deferred-tables: no {folder}/r*_{renderer}/results.csv")
        runs[renderer] = [still_rows(p) for p in paths]
    rounds = {len(v) for v in runs.values()}
    if len(rounds) != 1:
        sys.exit(f"deferred-tables: renderers have different round counts {sorted(rounds)}")
    return runs


def cell(runs, renderer, key):
    got = [r[key] for r in runs[renderer] if key in r]
    if len(got) != len(runs[renderer]):
        sys.exit(f"deferred-tables: row {key} missing from a round of {renderer}")
    psnr = st.mean(float(r["psnr_db"]) for r in got)
    frame = st.median(float(r["gpu_frame_ms"]) for r in got)
    text = f"{psnr:.2f} dB, {frame:.1f} ms"
    if renderer == "forward":
        return text, frame
    fwd = [float(r[key]["gpu_frame_ms"]) for r in runs["forward"]]
    ratio = frame / st.median(fwd)
    per_round = [float(r["gpu_frame_ms"]) / f for r, f in zip(got, fwd)]
    mine = [float(r["gpu_frame_ms"]) for r in got]
    spread = max(max(fwd) / min(fwd), max(mine) / min(mine))
    mark = "" if abs(ratio - 1) > spread - 1 else "?"
    return text + f", x{ratio:.2f}{mark} ({min(per_round):.2f}-{max(per_round):.2f})", frame


def table(runs):
    lines = ["| filter, scale | " + " | ".join(RENDERERS) + " | forward spread over rounds |",
             "| --- |" + " ---: |" * (len(RENDERERS) + 1)]
    for key in ROWS:
        cells = [cell(runs, r, key)[0] for r in RENDERERS]
        fwd = [float(r[key]["gpu_frame_ms"]) for r in runs["forward"]]
        lines.append(f"| {key[0]} {key[1]} | " + " | ".join(cells) + f" | x{max(fwd) / min(fwd):.2f} |")
    return "\n".join(lines) + "\n"


def main(argv):
    if len(argv) not in (2, 4) or (len(argv) == 4 and argv[2] not in ("--write", "--check")):
        sys.exit(__doc__)
    text = table(load(argv[1]))
    if len(argv) == 2:
        sys.stdout.write(text)
        return
    doc = open(argv[3]).read()
    if BEGIN not in doc or END not in doc:
        sys.exit(f"deferred-tables: {argv[3]} has no {BEGIN} ... {END} markers")
    head, rest = doc.split(BEGIN, 1)
    current, tail = rest.split(END, 1)
    if argv[2] == "--check":
        if current.strip() != text.strip():
            sys.exit(f"deferred-tables: the table in {argv[3]} is not the one {argv[1]} gives:\n{text}")
        return
    with open(argv[3], "w") as f:
        f.write(head + BEGIN + "\n" + text + END + tail)


if __name__ == "__main__":
    main(sys.argv)
