#!/usr/bin/python3
# SPDX-License-Identifier: MIT
# Speed against error of the GPU volume renderers: reads docs/results/volume_speed_error.csv
# (written by `volpost_volume_bench --csv`) and draws docs/images/volume_speed_error.png.
# Needs Debian's python3-matplotlib (docs only).
import csv
import pathlib

import matplotlib
matplotlib.use("Agg")
import matplotlib.pyplot as plt

here = pathlib.Path(__file__).resolve().parent.parent
rows = list(csv.DictReader(open(here / "results" / "volume_speed_error.csv")))
markers = {"linear": "o", "iso-table": "s", "pre-integrated": "^", "sampling": "x",
           "vicp linear": "D", "vicp pre-integrated": "v", "vicp sampling": "1",
           "vicp-exact linear": "P", "vicp-exact pre-integrated": "*", "vicp-exact sampling": "2"}
fig, ax = plt.subplots(figsize=(7, 4.5), dpi=110)
for mesh in dict.fromkeys(r["mesh"] for r in rows):
    color = None
    for r in rows:
        if r["mesh"] != mesh:
            continue
        (line,) = ax.loglog(float(r["median_ms"]), max(float(r["rmse"]), 1e-8), markers[r["mode"]],
                            color=color, label=mesh if color is None else None)
        color = line.get_color()
for mode, m in markers.items():
    ax.plot([], [], m, color="gray", label=mode)
ax.set_xlabel("median ms per frame (512 x 512, llvmpipe)")
ax.set_ylabel("RMSE against the exact reference")
ax.set_title("GPU ray casting and cell projection (vicp): speed against error")
ax.grid(True, which="both", alpha=0.3)
ax.legend(fontsize=7, ncol=2)
fig.tight_layout()
fig.savefig(here / "images" / "volume_speed_error.png")
