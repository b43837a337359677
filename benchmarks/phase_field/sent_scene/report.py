#!/usr/bin/env python3
"""results.md, force.png and crack.png of benchmarks/phase_field/sent_scene
from runs/ (statistics of prm/sent_coarse.prm). Usage: report.py DIR"""
import glob
import os
import subprocess
import sys

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", ".."))
from runs_io import read_statistics, wall_time  # noqa: E402

here = sys.argv[1] if len(sys.argv) > 1 else os.path.dirname(os.path.abspath(__file__))
runs = os.path.join(here, "runs")
thickness, g_c, ligament = 2.5e-5, 2700.0, 0.5e-3  # m, J/m^2, m

rows = read_statistics(os.path.join(runs, "statistics"))
u = [r["u2_y"] * 1e3 for r in rows]  # mm
F = [r["F2_y"] / thickness * 1e-6 for r in rows]  # kN/mm per unit thickness
peak = max(range(len(F)), key=lambda i: F[i])
last = rows[-1]
wall = wall_time(os.path.join(runs, "screen.txt"))
with open(os.path.join(here, "results.md"), "w") as out:
    out.write("| quantity | value |\n|---|---|\n")
    out.write(f"| peak force F_max [kN/mm] | {F[peak]:.5f} at u = {u[peak]:.5f} mm (t = {rows[peak]['time']:.4f}) |\n")
    out.write(f"| last step | t = {last['time']:.4f}, u = {u[-1]:.5f} mm, F = {F[-1]:.5f} kN/mm "
              f"({F[-1] / F[peak]:.1%} of F_max) |\n")
    if "fracture_energy" in last:
        out.write(f"| fracture energy g_c int gamma [J] | {last['fracture_energy']:.4e} "
                  f"(g_c x ligament x thickness = {g_c * ligament * thickness:.4e}) |\n")
    for key in ("external_work", "stored_energy", "fracture_viscous_work", "energy_residual",
                "history_driving_work"):
        if key in last:
            out.write(f"| {key.replace('_', ' ')} [J] | {last[key]:.4e} |\n")
    if "history_driving_work" in last:
        # The balance with the history driver's work: what is left is the
        # time discretisation (backward Euler over steps where s jumps).
        W = last["external_work"]
        rest = [r["energy_residual"] + r["history_driving_work"] for r in rows]
        worst = max(range(len(rows)), key=lambda i: abs(rest[i]))
        out.write(f"| energy residual + history driving work [J] | {rest[-1]:.4e} at the end "
                  f"({rest[-1] / W:.1%} of W_ext; largest {rest[worst]:.4e} at t = "
                  f"{rows[worst]['time']:.4f}); energy residual alone {last['energy_residual'] / W:.1%} |\n")
    its = [int(r["newton_iterations"]) for r in rows]
    sep = [i for i, r in enumerate(rows) if r["time"] > rows[peak]["time"] and F[i] < 0.1 * F[peak]]
    if sep:
        after = its[sep[0]:]
        out.write(f"| after the separation (F < 10 % of F_max, from t = {rows[sep[0]]['time']:.4f}) | "
                  f"{len(after)} steps, {sum(after)} Newton iterations, "
                  f"{sum(int(r['cutbacks']) for r in rows[sep[0]:])} cut-backs, "
                  f"last dt {last['dt']:.3g} |\n")
    out.write(f"| load steps, Newton iterations, cut-backs | {len(rows) - 1}, "
              f"{sum(int(r['newton_iterations']) for r in rows)}, {sum(int(r['cutbacks']) for r in rows)} |\n")
    if wall:
        out.write(f"| wall time [s] | {wall:.0f} |\n")
print(open(os.path.join(here, "results.md")).read())
try:
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
except ImportError:
    sys.exit(0)
fig, ax = plt.subplots(figsize=(6, 4.2))
ax.plot(u, F, ".-", ms=3)
ax.set_xlabel("top displacement u [mm]")
ax.set_ylabel("force per unit thickness [kN/mm]")
ax.set_title("prm/sent_coarse.prm: notched tension to complete fracture", fontsize=9)
ax.grid(True, alpha=0.3)
fig.tight_layout()
fig.savefig(os.path.join(here, "force.png"), dpi=120)
outputs = sorted(glob.glob(os.path.join(runs, "solution_*.pvtu")))
if outputs:
    subprocess.run([sys.executable, os.path.join(here, "..", "..", "..", "scripts", "vtu_slice.py"),
                    outputs[-1], "s", os.path.join(here, "crack.png"), "0",
                    f"s at u = {u[-1]:.4f} mm ({os.path.basename(outputs[-1])})"], check=True)
