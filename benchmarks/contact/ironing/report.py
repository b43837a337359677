#!/usr/bin/env python3
"""Table (results.md) and plot (ironing.png) of benchmarks/contact/ironing:
the die's drag F_x and normal force F_y against its travel, the friction /
normal contact force ratio, Newton iterations. Usage: report.py DIR"""
import math
import os
import sys

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", ".."))
from runs_io import read_statistics, wall_time  # noqa: E402

here = sys.argv[1] if len(sys.argv) > 1 else os.path.dirname(os.path.abspath(__file__))
d = os.path.join(here, "runs")
rows = read_statistics(os.path.join(d, "statistics"))
wall = wall_time(os.path.join(d, "screen.txt")) or float("nan")


def norm(r, what):
    return math.sqrt(sum(r["contact1_" + what + "_" + c] ** 2 for c in "xyz"))


sliding = [r for r in rows if r["time"] > 1.15]
drag = [r["F2_x"] for r in sliding]
normal = [-r["F2_y"] for r in sliding]
jump = max(abs(b - a) / abs(b) for a, b in zip(drag, drag[1:]))
jump_n = max(abs(b - a) / abs(b) for a, b in zip(normal, normal[1:]))
ratio = [norm(r, "friction") / norm(r, "force") for r in sliding]
with open(os.path.join(here, "results.md"), "w") as out:
    out.write("| quantity | value |\n|---|---|\n")
    out.write(f"| steps (press 10, slide 20) | {len(rows) - 1} |\n")
    out.write(f"| drag F_x while sliding [N] | {min(drag):.3f} .. {max(drag):.3f} |\n")
    out.write(f"| normal force F_y while sliding [N] | {min(normal):.3f} .. {max(normal):.3f} |\n")
    out.write(f"| largest step-to-step change, drag / normal force | {jump:.2%} / {jump_n:.2%} |\n")
    out.write(f"| F_x / F_y (friction + ploughing) | {min(d / n for d, n in zip(drag, normal)):.4f} .. "
              f"{max(d / n for d, n in zip(drag, normal)):.4f} |\n")
    out.write(f"| friction / normal contact force | {min(ratio):.7f} .. {max(ratio):.7f} |\n")
    out.write(f"| slipping / active nodes while sliding | "
              f"{min(r['contact1_slipping_nodes'] / r['contact1_active_nodes'] for r in sliding):.2f} |\n")
    out.write(f"| max penetration [m] | {max(r['contact1_max_penetration'] for r in rows):.1e} |\n")
    out.write(f"| energy residual / W_ext at the end | "
              f"{rows[-1]['energy_residual'] / rows[-1]['external_work']:.2e} |\n")
    out.write(f"| Newton iterations per step (all multiplier updates), mean | "
              f"{sum(r['newton_iterations'] for r in rows[1:]) / (len(rows) - 1):.1f} |\n")
    out.write(f"| multiplier updates per step, mean | "
              f"{sum(r['contact_augmentations'] for r in rows[1:]) / (len(rows) - 1):.1f} |\n")
    out.write(f"| wall time [s] | {wall:.0f} |\n")
print(open(os.path.join(here, "results.md")).read())
try:
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
except ImportError:
    sys.exit(0)
travel = [1e3 * r["u2_x"] for r in rows]
fig, ax = plt.subplots(1, 2, figsize=(10, 4))
ax[0].plot(travel, [r["F2_x"] for r in rows], "o-", ms=3, label="drag F_x")
ax[0].plot(travel, [-r["F2_y"] for r in rows], "s-", ms=3, label="normal force F_y")
ax[0].plot(travel, [norm(r, "friction") for r in rows], "--", label="friction force (contact)")
ax[0].set_xlabel("die travel along the slab [mm]")
ax[0].set_ylabel("force on the die's top [N] (2 mm thick slice)")
ax[0].legend(fontsize=8)
ax[1].plot(travel, [r["contact1_slipping_nodes"] for r in rows], label="slipping nodes")
ax[1].plot(travel, [r["contact1_sticking_nodes"] for r in rows], label="sticking nodes")
ax[1].plot(travel, [r["newton_iterations"] for r in rows], label="Newton iterations")
ax[1].set_xlabel("die travel along the slab [mm]")
ax[1].legend(fontsize=8)
for a in ax:
    a.grid(alpha=0.3)
plt.tight_layout()
plt.savefig(os.path.join(here, "ironing.png"), dpi=120)
