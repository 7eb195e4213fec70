#!/usr/bin/env python3
"""Tessellation at one absolute budget (Docs/Tessellation.md), from committed data.

Reads the folder that `ONE_BUDGET=DIR scripts/measure-tessellation.sh` wrote:
  budget.txt   native_off_ms budget_ms refresh_hz (the budget: half the untessellated native frame)
  sweep.txt    round cfg scale gpu_frame_ms (fixed scales, both modes interleaved)
  settled.txt  cfg settled lo hi gpu_frame_ms frames (the article law at that one budget)
  bench_<cfg>/results.json  PSNR and FLIP at the settled scale against that mode's reference
  counts.txt   the "counts ..." lines of SceneTessellation.ArenaCountsAtTheDefaultSettings
and prints the tables; --write DOC replaces them between <!-- tess-budget:begin --> and
<!-- tess-budget:end -->, --check DOC exits 1 when DOC's differ.

Usage: scripts/tessellation-tables.py DIR[,DIR...] [--write|--check Docs/Tessellation.md]
(several folders: one block of tables per run, in the order given)
"""
import collections
import json
import os
import statistics as st
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import doc_tables  # noqa: E402

BEGIN, END = "<!-- tess-budget:begin -->", "<!-- tess-budget:end -->"


def lines(folder, name):
    path = os.path.join(folder, name)
    return [l.split() for l in open(path) if l.strip()] if os.path.exists(path) else []


def sweep_table(folder, budget):
    times = collections.defaultdict(list)
    for _, cfg, scale, ms in lines(folder, "sweep.txt"):
        times[(cfg, float(scale))].append(float(ms))
    scales = sorted({s for _, s in times}, reverse=True)
    out = ["| scale | off: GPU frame ms (median over rounds; range) | on: GPU frame ms | on / off | "
           "off within the budget | on within the budget |",
           "| ---: | ---: | ---: | ---: | :---: | :---: |"]
    for s in scales:
        off, on = times.get(("off", s), []), times.get(("on", s), [])
        if not off or not on:
            continue
        mo, mn = st.median(off), st.median(on)
        out.append(f"| {s:.2f} | {mo:.1f} ({min(off):.1f}-{max(off):.1f}) | {mn:.1f} ({min(on):.1f}-{max(on):.1f}) | "
                   f"x{mn / mo:.2f} | {'yes' if max(off) <= budget else 'no' if min(off) > budget else 'spans'} | "
                   f"{'yes' if max(on) <= budget else 'no' if min(on) > budget else 'spans'} |")
    return "\n".join(out) + "\n"


def bench_cell(folder, cfg):
    path = os.path.join(folder, f"bench_{cfg}", "results.json")
    if not os.path.exists(path):
        return "not measured"
    rows = [r for r in json.load(open(path))["rows"] if r["filter"] == "taa" and not r["moving"]]
    nat = [r for r in json.load(open(path))["rows"] if r["filter"] == "native" and not r["moving"]]
    if not rows:
        return "not measured"
    r = rows[0]
    text = f"TAA {r['scale']:.3f}: {r['psnr_db']:.2f} dB, FLIP {r['flip']:.4f}"
    if nat:
        text += f" (native: {nat[0]['psnr_db']:.2f} dB, {nat[0]['flip']:.4f})"
    return text


def settled_table(folder, budget):
    out = ["| tessellation | settled scale (median of the last third; range) | GPU frame there ms | frames | "
           "image error at the settled scale (own 4x4 reference) |",
           "| --- | ---: | ---: | ---: | --- |"]
    for cfg, scale, lo, hi, ms, frames in lines(folder, "settled.txt"):
        floor = " (the law's floor)" if float(scale) <= 0.3 + 1e-6 else ""
        out.append(f"| {cfg} | {float(scale):.3f}{floor} ({float(lo):.3f}-{float(hi):.3f}) | {float(ms):.1f} "
                   f"(budget {budget:.1f}) | {frames} | {bench_cell(folder, cfg)} |")
    return "\n".join(out) + "\n"


def counts_table(folder):
    out = ["| camera | tessellation | scale | primitives | hull-shader invocations | domain-shader invocations |",
           "| --- | --- | ---: | ---: | ---: | ---: |"]
    names = {"0": "cinematic (t = 1 s)", "1": "camera_static1"}
    for f in lines(folder, "counts.txt"):
        if f[0] != "counts":
            continue
        v = dict(zip(f[1::2], f[2::2]))
        out.append(f"| {names.get(v['camera'], v['camera'])} | {'on' if v['tessellation'] == '1' else 'off'} | "
                   f"{float(v['scale']):.2f} | {int(v['primitives']):,} | {int(v['hs']):,} | {int(v['ds']):,} |")
    return "\n".join(out) + "\n"


def tables(folder):
    native, budget, hz = (float(x) for x in lines(folder, "budget.txt")[0])
    load = " ".join(open(os.path.join(folder, "load.txt")).read().split()) if os.path.exists(
        os.path.join(folder, "load.txt")) else "?"
    return (f"Data: `{folder}`. Untessellated native frame {native:.1f} ms; the one budget for both modes "
            f"{budget:.1f} ms (`--refresh {hz}`). Machine load: {load}.\n\n"
            + sweep_table(folder, budget) + "\n" + settled_table(folder, budget) + "\n" + counts_table(folder))


def all_tables(arg):
    """One block of tables per folder of the comma-separated list."""
    folders = arg.split(",")
    return "\n".join((f"**Run {i + 1}.** " if len(folders) > 1 else "") + tables(f) for i, f in enumerate(folders))


if __name__ == "__main__":
    sys.exit(doc_tables.main(sys.argv, __doc__, all_tables, BEGIN, END, "tessellation-tables"))
