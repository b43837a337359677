#!/usr/bin/env python3
"""Plots results.txt of run.sh: error against solve + assembly time."""
import os
import sys
import matplotlib
matplotlib.use("Agg")
import matplotlib.pyplot as plt

here = os.path.dirname(os.path.abspath(__file__))
rows = [l.split() for l in open(os.path.join(here, "results.txt")) if l[0] in "ms"]
fig, axes = plt.subplots(1, 2, figsize=(10, 4.2))
for ax, problem, column, label in [(axes[0], "manufactured", 7, "broken H2 error"),
                                   (axes[1], "strip", 5, "relative error of Gamma(5 l_f)")]:
    for degree, marker in [("2", "o"), ("3", "s")]:
        for solver, style in [("direct", "-"), ("cg-amg", "--")]:
            sel = [r for r in rows if r[0] == problem and r[1] == degree and r[2] == solver]
            if not sel:
                continue
            t = [float(r[8]) + float(r[9]) for r in sel]
            e = [float(r[column]) for r in sel]
            ax.loglog(t, e, style + marker, label=f"Q{degree} {solver}")
    ax.set_xlabel("assembly + solve time [s]")
    ax.set_ylabel(label)
    ax.set_title(problem)
    ax.grid(True, which="both", lw=0.3)
    ax.legend(fontsize=8)
fig.tight_layout()
fig.savefig(os.path.join(here, "work_precision.png"), dpi=110)
