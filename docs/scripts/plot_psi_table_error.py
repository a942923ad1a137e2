#!/usr/bin/python3
# SPDX-License-Identifier: MIT
# Plots docs/results/psi_table_error.csv (written by `volpost_optics_bench --csv`) to
# docs/images/psi_table_error.png. Needs Debian's python3-matplotlib (docs only).
import csv
import pathlib

import matplotlib
matplotlib.use("Agg")
import matplotlib.pyplot as plt

here = pathlib.Path(__file__).resolve().parent.parent
rows = list(csv.DictReader(open(here / "results" / "psi_table_error.csv")))
n = [int(r["resolution"]) for r in rows]
fig, ax = plt.subplots(figsize=(6, 4), dpi=110)
ax.loglog(n, [float(r["max_abs_error"]) for r in rows], "o-", label="max |error|")
ax.loglog(n, [float(r["rms_error"]) for r in rows], "s-", label="RMS error")
ax.loglog(n, [4.0 / x**2 * 1e2 for x in n], "k:", label="slope -2")
ax.set_xlabel("psi table resolution N (N x N, float, bilinear)")
ax.set_ylabel("absolute error of psi")
ax.set_title("psi table vs exact psi, optical depths 1e-4..1e3")
ax.set_xticks(n, [str(x) for x in n])
ax.grid(True, which="both", alpha=0.3)
ax.legend()
fig.tight_layout()
fig.savefig(here / "images" / "psi_table_error.png")
