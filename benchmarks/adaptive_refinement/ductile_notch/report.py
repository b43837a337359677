#!/usr/bin/env python3
"""results.md of run.sh: the adaptive ductile notch against the mesh graded by
hand, step by step (force per unit thickness, max alpha, plastic work) and at
the end (external work, crack energy, energy residual), with unknowns and
time."""
import os
import sys

here = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, os.path.join(here, "..", ".."))
from runs_io import read_statistics, wall_time  # noqa: E402

runs = {}
for name, thickness in (("fixed", 1e-4), ("adaptive", 2e-4)):  # slab thickness [m]
    d = os.path.join(here, "runs", name)
    if os.path.exists(os.path.join(d, "statistics")):
        rows = read_statistics(os.path.join(d, "statistics"))
        screen = open(os.path.join(d, "screen.txt")).read()
        dofs0 = int(screen.split("DoFs: ")[1].split()[0])
        runs[name] = dict(rows=rows, t=thickness, wall=wall_time(os.path.join(d, "screen.txt")),
                          dofs=[int(r.get("dofs", dofs0)) for r in rows])
if len(runs) < 2:
    sys.exit("both runs are needed")
f, a = runs["fixed"], runs["adaptive"]


def per_thickness(run, row, column, scale=1.0):
    return row[column] / run["t"] * scale


with open(os.path.join(here, "results.md"), "w") as out:
    out.write("# Ductile notch: adaptive (h = 2 l_f -> l_f) against the mesh graded by hand "
              "(run.sh)\n\nPer unit thickness: force [kN/mm], energies [J/m]. Same load steps "
              "where both have them.\n\n")
    out.write("| t | F fixed | F adaptive | max alpha fixed | adaptive | W_p fixed | adaptive | "
              "s_max fixed | adaptive | DoFs adaptive |\n|---|---|---|---|---|---|---|---|---|---|\n")
    at = {round(r["time"], 6): (r, n) for r, n in zip(a["rows"], a["dofs"])}
    for r in f["rows"]:
        t = round(r["time"], 6)
        if t not in at:
            continue
        q, n = at[t]
        out.write(f"| {t:g} | {per_thickness(f, r, 'F2_y', 1e-6):.4f} | "
                  f"{per_thickness(a, q, 'F2_y', 1e-6):.4f} | {r['max_alpha']:.4f} | "
                  f"{q['max_alpha']:.4f} | {per_thickness(f, r, 'plastic_work'):.4g} | "
                  f"{per_thickness(a, q, 'plastic_work'):.4g} | {r['max_s']:.3f} | "
                  f"{q['max_s']:.3f} | {n} |\n")
    out.write("\n| mesh | F_max [kN/mm] | at u [um] | W_ext end | crack energy end | W_p end | "
              "energy residual end | unknowns (end) | Newton its | wall [s] |\n"
              "|---|---|---|---|---|---|---|---|---|---|\n")
    for name, run in (("graded by hand, h = l_f", f), ("adaptive, 2 l_f -> l_f", a)):
        rows = run["rows"]
        k = max(range(len(rows)), key=lambda i: rows[i]["F2_y"])
        e = rows[-1]
        out.write(f"| {name} | {per_thickness(run, rows[k], 'F2_y', 1e-6):.4f} | "
                  f"{rows[k]['u2_y'] * 1e6:.3g} | {per_thickness(run, e, 'external_work'):.4g} | "
                  f"{per_thickness(run, e, 'fracture_energy'):.4g} | "
                  f"{per_thickness(run, e, 'plastic_work'):.4g} | "
                  f"{per_thickness(run, e, 'energy_residual'):.3g} | {run['dofs'][-1]} | "
                  f"{int(sum(r['newton_iterations'] for r in rows))} | {run['wall']:.0f} |\n")
print(open(os.path.join(here, "results.md")).read())
