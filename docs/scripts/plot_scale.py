#!/usr/bin/python3
# SPDX-License-Identifier: MIT
# Plots the table `volpost_scale_bench` prints (saved as docs/results/scale_bench_cpu.md) to
# docs/images/scale.png: seconds per stage to the first volume picture, and host bytes per
# tet, against the number of tets. Needs Debian's python3-matplotlib (docs only).
import pathlib
import sys

import matplotlib
matplotlib.use("Agg")
import matplotlib.pyplot as plt

here = pathlib.Path(__file__).resolve().parent.parent
source = pathlib.Path(sys.argv[1]) if len(sys.argv) > 1 else here / "results" / "scale_bench_cpu.md"
rows = []
header = None
for line in source.read_text().splitlines():
    if not line.startswith("|") or line.startswith("|---"):
        continue
    cells = [c.strip() for c in line.strip("|").split("|")]
    if header is None:
        header = cells
        continue
    rows.append(dict(zip(header, cells)))

tets = [float(r["tets"]) / 1e6 for r in rows]
stages = ["read s", "checks s", "tetrahedra s", "values s", "renderer build s", "first frame s"]
names = ["read", "model checks", "tetrahedra", "values", "renderer build", "first frame"]
fig, (left, right) = plt.subplots(1, 2, figsize=(10, 4), dpi=110)
bottom = [0.0] * len(rows)
labels = [f"{t:.1f}M" for t in tets]
for stage, name in zip(stages, names):
    values = [float(r[stage]) for r in rows]
    left.bar(labels, values, bottom=bottom, label=name)
    bottom = [b + v for b, v in zip(bottom, values)]
for x, total in zip(labels, bottom):
    left.annotate(f"{total:.1f} s", (x, total), ha="center", va="bottom", fontsize=8)
left.set_xlabel("tetrahedra")
left.set_ylabel("seconds from the file to the first picture")
left.set_title("time to the first volume picture (CPU ray caster)")
left.legend(fontsize=8)
right.plot(tets, [float(r["host peak B/tet"]) for r in rows], "o-", label="host peak (whole run)")
right.plot(tets, [float(r["read peak B/tet"]) for r in rows], "s-", label="host peak while reading")
right.axhline(64, color="k", linestyle=":", label="goal: 64 B/tet")
right.set_xscale("log")
right.set_xlabel("tetrahedra (millions)")
right.set_ylabel("bytes per tet above the process's start")
right.set_ylim(bottom=0)
right.set_title("host memory per tet")
right.grid(True, alpha=0.3)
right.legend(fontsize=8)
fig.tight_layout()
fig.savefig(here / "images" / "scale.png")
print(here / "images" / "scale.png")
