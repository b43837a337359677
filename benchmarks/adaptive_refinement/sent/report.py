#!/usr/bin/env python3
"""Writes results.md and sent_adaptive.png from runs/*/statistics of run.sh:
the adaptive runs against the meshes refined by hand along the crack path
(benchmarks/phase_field/sent/runs/lf0.0075, the same scene and solver),
each counted up to the step after the peak (or to the limit point where a
run stopped: there the last converged force is F_max, as in
benchmarks/phase_field/sent)."""
import glob
import os
import re
import sys

here = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, os.path.join(here, "..", ".."))
from runs_io import read_statistics  # noqa: E402

uniform_root = os.path.join(here, "..", "..", "phase_field", "sent", "runs", "lf0.0075")
# The meshes by hand: run folder -> (label, slab thickness [mm]: one element,
# l_f / h); the last is the reference run again with the code of run.sh's
# last run, for the wall time.
by_hand_runs = {
    os.path.join(uniform_root, "q2-h1-monolithic-direct-dt0.05-box6"):
        ("by hand, h = l_f", 0.0075, 1),
    os.path.join(uniform_root, "q2-h2-monolithic-direct-dt0.05-box6"):
        ("by hand, h = l_f/2", 0.00375, 2),
    os.path.join(here, "runs", "by-hand-h2-session36"):
        ("by hand, h = l_f/2, rerun 2026-12-04", 0.00375, 2)}
# run.sh's base meshes: name prefix -> (slab thickness [mm], in-plane h / l_f
# of the cells that are refined, label)
bases = {"": (0.00375, 8, "from h = 8 l_f"),
         "graded-": (0.0075, 1, "from the mesh by hand at h = l_f")}


def load(run, label, thickness_mm, refinement):
    """refinement: l_f / h of the finest cells."""
    rows = read_statistics(os.path.join(run, "statistics"))
    screen = open(os.path.join(run, "screen.txt")).read()
    force = [r["F2_y"] / thickness_mm / 1e3 for r in rows]  # kN/mm
    disp = [r["u2_y"] * 1e3 for r in rows]  # mm
    k = max(range(len(force)), key=lambda i: force[i])
    stopped = "Load stepping/Minimum time step" in screen
    complete = k < len(force) - 1 or stopped
    # At a limit point (the run stopped): F_max lies between the last
    # converged force and that force extrapolated with the last slope to
    # the smallest failed load above it.
    times = [r["time"] for r in rows]
    upper = force[k]
    if stopped and k == len(force) - 1 and len(rows) > 2:
        failed = [float(t) for t in re.findall(r"at t = ([\d.e+-]+) failed", screen)]
        above = [t for t in failed if t > times[-1]]
        if above:
            slope = (force[-1] - force[-2]) / (times[-1] - times[-2])
            upper = force[-1] + max(slope, 0.) * (min(above) - times[-1])
    upto = rows[:k + 2]
    last = upto[-1]
    dofs = [int(r["dofs"]) for r in upto] if "dofs" in rows[0] else \
        [int(re.search(r"DoFs: (\d+)", screen).group(1))]
    cells = int(last["cells"]) if "cells" in last else None
    at = [f for f, t in zip(force, times) if abs(t - 0.45) < 1e-9]
    return dict(label=label, refinement=refinement, peak=force[k], upper=upper, u_peak=disp[k],
                f_045=at[0] if at else float("nan"), dofs_peak=dofs[min(k, len(dofs) - 1)],
                dofs_max=max(dofs), cells=cells, complete=complete, stopped=stopped,
                newton=int(sum(r["newton_iterations"] for r in upto)),
                refinements=int(sum(r.get("refinements", 0) for r in upto)),
                cutbacks=int(sum(r["cutbacks"] for r in upto)),
                wall=last["wall_time"], force=force, disp=disp)


runs = []
for d, (label, t, k) in by_hand_runs.items():
    if os.path.exists(os.path.join(d, "statistics")):
        runs.append(load(d, label, t, k))
for d in sorted(glob.glob(os.path.join(here, "runs", "*level*"))):
    if os.path.exists(os.path.join(d, "statistics")):
        m = re.match(r"(graded-)?level(\d+)-s([\d.]+)(?:-dtmin([\d.e-]+))?$", os.path.basename(d))
        thickness, h0, origin = bases[m.group(1) or ""]
        level = int(m.group(2))
        h = f"l_f/{2**level // h0}" if 2**level > h0 else f"{h0 // 2**level} l_f"
        dtmin = f", dt_min = {m.group(4)}" if m.group(4) else ""
        runs.append(load(d, f"adaptive {origin}, level {level} (h = {h}), s > {m.group(3)}{dtmin}",
                         thickness, 2**level / h0))
ref = next((r for r in runs if r["label"] == "by hand, h = l_f/2"), None)

with open(os.path.join(here, "results.md"), "w") as out:
    out.write("# Notched tension at l_f = 0.0075 mm: adaptive refinement against meshes refined "
              "by hand (run.sh)\n\n")
    out.write("Counts and times up to the step after the peak, or to the limit point where the "
              "run stopped (eta_f = 0: the crack turns unstable just after the peak). DoFs: at "
              "the peak and the most before it (adaptive meshes grow). The hand-made meshes' rows "
              "are those of benchmarks/phase_field/sent (runs/lf0.0075, 2 ranks, another day); "
              "the adaptive runs' ranks are in their screen.txt.\n\n")
    out.write("| mesh | F at u = 0.0045 mm [kN/mm] | vs by hand h = l_f/2 | F_max [kN/mm] | "
              "bracket at the limit point | u at F_max [mm] | vs by hand h = l_f/2 | DoFs at peak | most DoFs | Newton its | refinements | "
              "cut-backs | wall [s] |\n")
    out.write("|---|---|---|---|---|---|---|---|---|---|---|---|---|\n")
    for r in runs:
        diff = f"{(r['peak'] - ref['peak']) / ref['peak']:+.2e}" if ref else "-"
        flag = "" if r["complete"] else " (incomplete)"
        bracket = f"[{r['peak']:.5f}, {r['upper']:.5f}]" if r["upper"] > r["peak"] else "-"
        d045 = f"{(r['f_045'] - ref['f_045']) / ref['f_045']:+.2e}" if ref else "-"
        out.write(f"| {r['label']}{flag} | {r['f_045']:.5f} | {d045} | {r['peak']:.5f} | {bracket} | {r['u_peak']:.5g} | {diff} | "
                  f"{r['dofs_peak']} | {r['dofs_max']} | {r['newton']} | {r['refinements']} | "
                  f"{r['cutbacks']} | {r['wall']:.0f} |\n")
print(open(os.path.join(here, "results.md")).read())

try:
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
except ImportError:
    sys.exit(0)
fig, (ax, conv) = plt.subplots(1, 2, figsize=(12, 4.8), width_ratios=[3, 2])
for r in runs:
    ax.plot(r["disp"], r["force"], marker=".", label=r["label"])
ax.set_xlim(0.0044, 0.0047)
ax.set_ylim(0.575, 0.61)
ax.set_xlabel("top displacement [mm]")
ax.set_ylabel("force per thickness [kN/mm]")
ax.set_title("notched tension, l_f = 0.0075 mm, near the peak")
ax.grid(True, alpha=0.3)
ax.legend(fontsize=6)
# F_max against the finest h, where the limit point is bracketed closely.
for r in runs:
    if r["complete"] and r["upper"] - r["peak"] < 1e-3:
        hand = r["label"].startswith("by hand")
        conv.plot(1 / r["refinement"], r["peak"], "o" if hand else "s",
                  color="C0" if hand else "C3", fillstyle="full" if hand else "none")
conv.set_xscale("log", base=2)
conv.set_xlabel("h / l_f at the crack (dots: by hand, squares: adaptive)")
conv.set_ylabel("F_max [kN/mm]")
conv.set_title("F_max under refinement")
conv.grid(True, alpha=0.3)
fig.tight_layout()
fig.savefig(os.path.join(here, "sent_adaptive.png"), dpi=120)
