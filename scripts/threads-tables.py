#!/usr/bin/env python3
"""The recording-threads table of Docs/Threads.md, from committed data.

Reads DIR/*.txt written by scripts/measure-threads.sh (drr_scene_record_bench
outputs: each run 10 alternating pairs of 1 thread and N threads, every pair's
ratio of the two medians of its frames' Scene::Render times) and prints one
row per scene: the pooled pairs' median ratio with its distribution-free 95 %
interval (order statistics of the median), the runs' own medians, the chunk
times and a verdict against that row's question:
  props        the many-object Arena, 2 threads against 1: at most 0.65?
  auto         the Arena, the automatic mode against 1 thread: not slower?
  arena2       the Arena, 2 threads against 1: do two threads pay (below 1)?
  props-N      N props, 2 threads against 1: do two threads pay (below 1)?
A folder of before-R.txt and after-R.txt runs (scripts/compare-recording.sh:
two builds side by side) gives instead one row per thread count: each build's
median Scene::Render time and the paired after / before ratio (run R's pair i
of one build with run R's pair i of the other) with its interval; with
contention-before-R.txt and contention-after-R.txt (the benchmark's
--contention runs) a second table: per chunk, each build's ratio of the
chunk's time beside the other thread to its time alone, and after / before
paired the same way; where the after build's runs print them, a third: where
its frames' time goes, per thread count (the medians over the runs of each
run's median Render, draw-list build, chunk per thread, workers'
FinishCommandList, wait for the workers and list executions, the frames in
which the caller drew a worker's chunk and, where the runs print them, the
units of workers' chunks it drew). Where the runs print it (measure-threads'
many-object Arena, or the after build), one more: the N-thread frames split
by whether every worker was running before the draw list was published, each
part's median Render and its ratio to the run's one-thread median Render.
A verdict is given only where the interval lies wholly on one side of the
bound; otherwise "cannot decide". With --write DOC the table replaces the one
between <!-- threads-tables:begin NAME --> and <!-- threads-tables:end NAME -->
in DOC, NAME being DIR's last component (one table per measurement); --check
DOC exits 1 when it differs.

Usage: scripts/threads-tables.py DIR [--write|--check Docs/Threads.md]
"""
import glob
import math
import os
import re
import statistics as st
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import doc_tables  # noqa: E402


def markers(data_dir):
    name = os.path.basename(os.path.normpath(data_dir))
    return f"<!-- threads-tables:begin {name} -->", f"<!-- threads-tables:end {name} -->"


PAIR = re.compile(r"^pair \d+: 1 thread ([\d.]+) ms, (\d+) threads ([\d.]+) ms \(medians\), ratio ([\d.]+)")
CHUNK = re.compile(r"^(\d+) thread\(s\): chunk ms per thread \(medians\) ([\d. /]+);")
FINISH = re.compile(r"^(\d+) thread\(s\): chunk ms .*; FinishCommandList ms ([\d. /]+)$")
SERIAL = re.compile(r"^(\d+) thread\(s\): Render ([\d.]+) ms, draw list ([\d.]+) ms, wait for the workers ([\d.]+) ms, "
                    r"list executions ([\d.]+) ms \(medians\); a worker's chunk drawn by the caller in (\d+) of (\d+) frames"
                    r"(?:, (\d+) units of workers' chunks)?")
SERIAL_MS = ("render", "plan", "wait", "execute")  # SERIAL's times, in its group order
ON_TIME = re.compile(r"^(\d+) thread\(s\): every worker running before the draw list was published in (\d+) of (\d+) "
                     r"frames; Render ([\d.]+) ms in those, ([\d.]+) ms in the others")
DRAWS = re.compile(r"^draws per thread at \d+ threads: ([\d +]+)")
CONTENTION = re.compile(r"^chunk (\d+) ratios:((?: [\d.]+)*)$")
ALONE = re.compile(r"^chunk (\d+) \(([^)]*)\): alone ([\d.]+) ms")


def median_interval(values):
    """The sample median and a 95 % distribution-free interval for the median."""
    xs = sorted(values)
    n = len(xs)
    k = 0  # largest k with P(Binomial(n, 1/2) <= k) <= 0.025
    cumulative = 0.0
    for j in range(n + 1):
        cumulative += math.comb(n, j) / 2 ** n
        if cumulative > 0.025:
            break
        k = j + 1
    if k == 0:
        return st.median(xs), xs[0], xs[-1]
    return st.median(xs), xs[k - 1], xs[n - k]


def parse(path):
    run = {"ratios": [], "ms": {1: [], "N": []}, "threads": 0, "chunks": {}, "draws": "", "finish": {}, "serial": {}, "on_time": {}}
    for line in open(path):
        if m := PAIR.match(line):
            run["ratios"].append(float(m.group(4)))
            run["ms"][1].append(float(m.group(1)))
            run["ms"]["N"].append(float(m.group(3)))
            run["threads"] = int(m.group(2))
        elif m := CHUNK.match(line):
            run["chunks"][int(m.group(1))] = [float(x) for x in m.group(2).split("/")]
            if f := FINISH.match(line.rstrip("\n")):
                run["finish"][int(f.group(1))] = [float(x) for x in f.group(2).split("/")]
        elif m := SERIAL.match(line):
            run["serial"][int(m.group(1))] = {
                **{key: float(m.group(k)) for k, key in enumerate(SERIAL_MS, start=2)},
                "taken": int(m.group(6)), "frames": int(m.group(7)),
                "units": int(m.group(8)) if m.group(8) is not None else None}
        elif m := ON_TIME.match(line):
            run["on_time"][int(m.group(1))] = {"frames": int(m.group(2)), "of": int(m.group(3)),
                                               "render": float(m.group(4)), "late_render": float(m.group(5))}
        elif m := DRAWS.match(line):
            run["draws"] = m.group(1).strip()
    return run


def parse_contention(path):
    """Per chunk: every frame pair's beside / alone ratio, the chunk's label and its median time alone."""
    run = {}
    for line in open(path):
        if m := CONTENTION.match(line.rstrip("\n")):
            run.setdefault(int(m.group(1)), {})["ratios"] = [float(x) for x in m.group(2).split()]
        elif m := ALONE.match(line):
            run.setdefault(int(m.group(1)), {}).update(label=m.group(2), alone=float(m.group(3)))
    return run


def against_one(lo, hi, below, above):
    """The verdict of a ratio's interval against 1: wholly below, wholly above, or neither."""
    return below if hi < 1.0 else above if lo > 1.0 else "cannot decide"


def pays(lo, hi):
    return against_one(lo, hi, "two threads pay", "two threads cost")


def interval_text(med, lo, hi):
    return f"**{med:.3f}** [{lo:.3f}, {hi:.3f}]"


def question(name):
    if name == "props":
        return "many-object Arena (2,938 draws), 2 / 1 thread", lambda lo, hi: (
            "met (at most 0.65)" if hi <= 0.65 else "not met" if lo > 0.65 else "cannot decide")
    if name == "auto":
        return "Arena (59 draws), automatic / 1 thread", lambda lo, hi: (
            "not slower" if lo <= 1.0 else "slower")
    if name == "arena2":
        return "Arena (59 draws), 2 / 1 thread", pays
    props = name.split("-")[1]
    return f"Arena + {props} props, 2 / 1 thread", pays


def chunk_text(runs, threads):
    per = [r["chunks"].get(threads) for r in runs if r["chunks"].get(threads)]
    if not per:
        return "-"
    return " / ".join(f"{st.median(c[k] for c in per):.2f}" for k in range(len(per[0])))


def comparison_table(groups):
    """Two builds side by side: before-R and after-R runs, paired."""
    before, after = groups["before"], groups["after"]
    out = ["| `Scene::Render` | runs x pairs | before, median ms | after, median ms | "
           "after / before: paired median [95 % interval] | verdict |",
           "| --- | ---: | ---: | ---: | --- | --- |"]
    threads = before[0]["threads"]
    runs = min(len(before), len(after))
    for key, label in ((1, "1 thread"), ("N", f"{threads} threads")):
        b = [x for r in before for x in r["ms"][key]]
        a = [x for r in after for x in r["ms"][key]]
        paired = [y / x for rb, ra in zip(before, after) for x, y in zip(rb["ms"][key], ra["ms"][key])]
        med, lo, hi = median_interval(paired)
        out.append(f"| {label} | {runs} x {len(paired) // runs} | {st.median(b):.2f} | {st.median(a):.2f} | "
                   f"{interval_text(med, lo, hi)} | {against_one(lo, hi, 'faster', 'slower')} |")
    own = {side: interval_text(*median_interval([x for r in groups[side] for x in r["ratios"]]))
           for side in ("before", "after")}
    out.append(f"| {threads} / 1 thread, each build's own pairs | | {own['before']} | {own['after']} | | |")
    return "\n".join(out) + "\n"


def contention_table(folder):
    """The --contention runs of two builds: per chunk, beside / alone for each, and after / before paired."""
    runs = {side: [parse_contention(p) for p in sorted(glob.glob(os.path.join(folder, f"contention-{side}-*.txt")))]
            for side in ("before", "after")}
    for side in runs:  # a run still being written has no ratios yet
        runs[side] = [r for r in runs[side] if r and all("ratios" in c for c in r.values())]
    if not runs["before"] or not runs["after"]:
        return ""
    out = ["| chunk | frame pairs | alone, median ms (before / after) | before: beside / alone | "
           "after: beside / alone | after / before, paired | verdict |",
           "| --- | ---: | ---: | --- | --- | --- | --- |"]
    for chunk in sorted(runs["before"][0]):
        own = {side: [x for r in runs[side] for x in r[chunk]["ratios"]] for side in runs}
        alone = {side: st.median(r[chunk]["alone"] for r in runs[side]) for side in runs}
        paired = [a / b for rb, ra in zip(runs["before"], runs["after"])
                  for b, a in zip(rb[chunk]["ratios"], ra[chunk]["ratios"])]
        med, lo, hi = median_interval(paired)
        out.append(f"| {chunk} ({runs['before'][0][chunk]['label']}) | {len(own['before'])} / {len(own['after'])} | "
                   f"{alone['before']:.2f} / {alone['after']:.2f} | {interval_text(*median_interval(own['before']))} | "
                   f"{interval_text(*median_interval(own['after']))} | {interval_text(med, lo, hi)} | "
                   f"{against_one(lo, hi, 'less sharing', 'more sharing')} |")
    return "\n".join(out) + "\n"


def serial_table(runs):
    """Where the frame's time goes, 1 thread and N: medians over the runs of each run's medians."""
    runs = [r for r in runs if r["serial"]]
    if not runs:
        return ""
    units = any(v["units"] is not None for r in runs for v in r["serial"].values())
    out = ["| threads | runs | Render | draw list | chunk per thread (caller / workers) | workers' FinishCommandList | "
           "wait for the workers | list executions | frames with a worker's chunk drawn by the caller |"
           + (" units of workers' chunks drawn by the caller |" if units else ""),
           "| ---: | ---: | ---: | ---: | ---: | ---: | ---: | ---: | ---: |" + (" ---: |" if units else "")]
    for threads in sorted({t for r in runs for t in r["serial"]}):
        per = [r for r in runs if threads in r["serial"] and threads in r["chunks"]]
        col = {key: st.median(r["serial"][threads][key] for r in per) for key in SERIAL_MS}
        finish = " / ".join(f"{st.median(r['finish'][threads][k] for r in per):.3f}"
                            for k in range(1, len(per[0]["finish"].get(threads, []))))
        total = {key: sum(r["serial"][threads][key] or 0 for r in per) for key in ("taken", "frames", "units")}
        row = (f"| {threads} | {len(per)} | {col['render']:.3f} | {col['plan']:.3f} | {chunk_text(per, threads)} | "
               f"{finish or '-'} | {col['wait']:.3f} | {col['execute']:.3f} | {total['taken']} of {total['frames']} |")
        if units:
            row += f" {total['units']} |"
        out.append(row)
    return "\n".join(out) + "\n"


def on_time_table(runs):
    """N-thread frames split by whether every worker was running before the draw list was published:
    medians over the runs of each run's medians, and each part's Render over the run's 1-thread Render."""
    runs = [r for r in runs if r["on_time"] and 1 in r["serial"]]
    if not runs:
        return ""
    out = ["| threads | runs | frames with every worker running before the draw list was published | "
           "Render in those, ms | / 1 thread | Render in the others, ms | / 1 thread |",
           "| ---: | ---: | ---: | ---: | ---: | ---: | ---: |"]
    for threads in sorted({t for r in runs for t in r["on_time"]}):
        per = [r for r in runs if threads in r["on_time"]]
        parts = [r["on_time"][threads] for r in per]
        one = [r["serial"][1]["render"] for r in per]
        late = [(p, o) for p, o in zip(parts, one) if p["frames"] < p["of"]]
        late_ms = f"{st.median(p['late_render'] for p, _ in late):.3f}" if late else "-"
        late_ratio = f"{st.median(p['late_render'] / o for p, o in late):.3f}" if late else "-"
        out.append(f"| {threads} | {len(per)} | {sum(p['frames'] for p in parts)} of {sum(p['of'] for p in parts)} | "
                   f"{st.median(p['render'] for p in parts):.3f} | "
                   f"{st.median(p['render'] / o for p, o in zip(parts, one)):.3f} | {late_ms} | {late_ratio} |")
    return "\n".join(out) + "\n"


def tables(folder):
    groups = {}
    for path in sorted(glob.glob(os.path.join(folder, "*.txt"))):
        name = re.sub(r"-\d+\.txt$", "", os.path.basename(path))
        if name == os.path.basename(path).removesuffix(".txt"):
            continue  # not a run (load.txt)
        groups.setdefault(name, []).append(parse(path))
    if "before" in groups and "after" in groups:
        extra = [t for t in (contention_table(folder), serial_table(groups["after"]), on_time_table(groups["after"])) if t]
        return "\n".join([comparison_table(groups)] + extra)
    order = sorted(groups, key=lambda g: (g != "props", g != "auto", g != "arena2",
                                          int(g.split("-")[1]) if "-" in g else 0))
    out = ["| scene, comparison | draws per thread | runs x pairs | ratio: median [95 % interval] | runs' medians | "
           "chunk ms, 1 thread | chunk ms, N threads (main / worker) | verdict |",
           "| --- | --- | ---: | --- | --- | ---: | ---: | --- |"]
    for g in order:
        runs = [r for r in groups[g] if r["ratios"]]
        if not runs:
            continue
        ratios = [x for r in runs for x in r["ratios"]]
        med, lo, hi = median_interval(ratios)
        label, verdict = question(g)
        run_medians = ", ".join(f"{st.median(r['ratios']):.3f}" for r in runs)
        many = max((t for r in runs for t in r["chunks"] if t != 1), default=None)
        out.append(f"| {label} | {runs[0]['draws'] or '-'} | {len(runs)} x {len(ratios) // len(runs)} | "
                   f"{interval_text(med, lo, hi)} | {run_medians} | {chunk_text(runs, 1)} | "
                   f"{chunk_text(runs, many) if many is not None else '-'} | {verdict(lo, hi)} |")
    on_time = on_time_table(groups.get("props", []))
    return "\n".join(out) + "\n" + ("\nmany-object Arena:\n\n" + on_time if on_time else "")


if __name__ == "__main__":
    begin, end = markers(sys.argv[1]) if len(sys.argv) > 1 else ("", "")
    sys.exit(doc_tables.main(sys.argv, __doc__.split("Usage: ")[1], tables, begin, end, "threads-tables.py"))
