#!/usr/bin/env python3
"""Table (results.md) and plot (two_bodies.png) of
benchmarks/contact/two_bodies: every run in runs/*/ (statistics and the
screen log with the timer table). Usage: report.py DIR"""
import glob
import math
import os
import sys

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", ".."))
from runs_io import read_statistics, wall_time  # noqa: E402

here = sys.argv[1] if len(sys.argv) > 1 else os.path.dirname(os.path.abspath(__file__))
runs = {}
for d in sorted(glob.glob(os.path.join(here, "runs", "*"))):
    rows = read_statistics(os.path.join(d, "statistics"))
    wall = wall_time(os.path.join(d, "screen.txt"))
    runs[os.path.basename(d)] = dict(rows=rows, wall=wall or float("nan"))

with open(os.path.join(here, "results.md"), "w") as out:
    out.write("| run | steps | Newton iterations (all) | per step, mean / last 20 | multiplier updates | "
              "wall [s] | F on the block's top at the end [kN] | contact force [kN] | "
              "max penetration [m] | energy residual / W_ext |\n")
    out.write("|---|---|---|---|---|---|---|---|---|---|\n")
    for name, r in runs.items():
        rows = r["rows"][1:]
        its = [x["newton_iterations"] for x in rows]
        last = rows[-1]
        fc = math.sqrt(sum(last["contact1_force_" + c] ** 2 for c in "xyz"))
        out.write(f"| {name} | {len(rows)} | {sum(its):.0f} | {sum(its) / len(its):.1f} / "
                  f"{sum(its[-20:]) / len(its[-20:]):.1f} | "
                  f"{sum(x['contact_augmentations'] for x in rows):.0f} | {r['wall']:.0f} | "
                  f"{-last['F2_z'] / 1e3:.3f} | {fc / 1e3:.3f} | "
                  f"{max(x['contact1_max_penetration'] for x in rows):.1e} | "
                  f"{last['energy_residual'] / last['external_work']:.2e} |\n")
print(open(os.path.join(here, "results.md")).read())
try:
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
except ImportError:
    sys.exit(0)
fig, ax = plt.subplots(1, 2, figsize=(10, 4))
for name, r in runs.items():
    rows = r["rows"]
    ax[0].plot([-1e3 * x["u2_z"] for x in rows], [-x["F2_z"] / 1e3 for x in rows], label=name)
    ax[1].plot([x["step"] for x in rows[1:]], [x["newton_iterations"] for x in rows[1:]], label=name)
ax[0].set_xlabel("block top pushed down [mm]")
ax[0].set_ylabel("force on the block's top [kN]")
ax[1].set_xlabel("load step")
ax[1].set_ylabel("Newton iterations (all multiplier updates)")
for a in ax:
    a.grid(alpha=0.3)
    a.legend(fontsize=8)
plt.tight_layout()
plt.savefig(os.path.join(here, "two_bodies.png"), dpi=120)
