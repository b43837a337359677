"""Irreversibility benchmark report: results.md from
runs/{history,bound,history-and-bound}.

Per run: the smallest s_{n+1} - s_n over the phase-field DoFs and steps
(min_s_change), the largest s, steps, Newton iterations, cut-backs and run
time; the force per unit thickness (F2_y / h, h = 0.1 mm the slab's
thickness) at its peak and at the end, the crack energy at the end against
g_c x ligament (0.5 mm) x thickness, the largest |energy residual| / W_ext.
The two force curves are compared at the loads both runs reached.
"""
import os
import sys

import numpy as np

here = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, os.path.join(here, ".."))
sys.path.insert(0, os.path.join(here, "..", ".."))
from runs_io import read_statistics, wall_time  # noqa: E402

THICKNESS = 1e-4
LIGAMENT = 0.5e-3
G_C = 2800.


def evaluate(mode):
    directory = os.path.join(here, "runs", mode.replace(" ", "-"))
    rows = read_statistics(os.path.join(directory, "statistics"))
    u = np.array([r["u2_y"] for r in rows])
    F = np.array([r["F2_y"] for r in rows]) / THICKNESS
    w_ext = np.array([r["external_work"] for r in rows])
    res = np.array([r["energy_residual"] for r in rows])
    return dict(mode=mode, t=np.array([r["time"] for r in rows]), u=u, F=F,
                min_ds=min(r["min_s_change"] for r in rows[1:]),
                max_s=max(r["max_s"] for r in rows),
                steps=len(rows) - 1,
                newton=int(sum(r["newton_iterations"] for r in rows)),
                cutbacks=int(sum(r["cutbacks"] for r in rows)),
                time=wall_time(os.path.join(directory, "screen.txt")),
                peak=F.max(), end_F=F[-1], end_u=u[-1],
                crack=rows[-1]["fracture_energy"] / (G_C * LIGAMENT * THICKNESS),
                worst_res=max(abs(r) / w for r, w in zip(res[1:], w_ext[1:])))


def main():
    modes = ("history", "bound", "history and bound")
    runs = [evaluate(m) for m in modes if os.path.exists(
        os.path.join(here, "runs", m.replace(" ", "-"), "statistics"))]
    lines = ["# Irreversibility: the history field of psi+, the bound s >= s_n, both",
             "",
             "Coarse ductile notched plate (the ctest ductile_notch's scene, h = l_f = 0.1 mm),",
             "pulled to 24 um. F per unit thickness; min s change: smallest s_{n+1} - s_n",
             "over the phase-field DoFs and all steps; crack energy at the end / (g_c x",
             "ligament x thickness); residual: largest |energy residual| / W_ext.",
             "",
             "| Irreversibility | end u [um] | min s change | max s | steps | Newton its | cut-backs "
             "| run time [s] | peak F [kN/mm] | end F [kN/mm] | crack energy / g_c A | residual |",
             "|---|---|---|---|---|---|---|---|---|---|---|---|"]
    for r in runs:
        lines.append("| %s | %.1f | %.2e | %.4f | %d | %d | %d | %s | %.4f | %.4f | %.3f | %.1e |" % (
            r["mode"], r["end_u"] * 1e6, r["min_ds"], r["max_s"], r["steps"], r["newton"],
            r["cutbacks"], "%.0f" % r["time"] if r["time"] else "-", r["peak"] * 1e-6,
            r["end_F"] * 1e-6, r["crack"], r["worst_res"]))
    a = runs[0]
    for b in runs[1:]:
        common = np.intersect1d(np.round(a["t"], 12), np.round(b["t"], 12))
        fa = np.interp(common, a["t"], a["F"])
        fb = np.interp(common, b["t"], b["F"])
        diff = np.abs(fa - fb) / a["peak"]
        lines += ["",
                  "%s against %s, force curves at the %d loads both reached: largest difference "
                  "%.2e of the peak (at u = %.2f um)." % (
                      b["mode"], a["mode"], len(common), diff.max(),
                      np.interp(common[np.argmax(diff)], a["t"], a["u"]) * 1e6)]
    open(os.path.join(here, "results.md"), "w").write("\n".join(lines) + "\n")
    print("\n".join(lines))


main()
