#!/usr/bin/env python3
"""Table (results.md) and plot (scaling.png) of benchmarks/contact/scaling:
contact search, integration + tangent assembly (Newton iterations) and
integration + residual (line-search trials) time per call against the number
of slave faces. Usage: report.py DIR"""
import glob
import os
import re
import sys

here = sys.argv[1] if len(sys.argv) > 1 else os.path.dirname(os.path.abspath(__file__))
rows = []
for d in sorted(glob.glob(os.path.join(here, "runs", "n*")), key=lambda d: int(d.split("n")[-1])):
    screen = open(os.path.join(d, "screen.txt")).read()
    n = int(os.path.basename(d)[1:])

    def section(name):
        m = re.search(r"\| " + re.escape(name) + r"\s*\|\s*(\d+)\s*\|\s*([\d.e+-]+)s", screen)
        return (int(m.group(1)), float(m.group(2))) if m else (0, float("nan"))

    # The search is the contact module's begin step ("contact: search" in
    # runs made before the module lifecycle).
    search = section("contact: begin step")
    if search[0] == 0:
        search = section("contact: search")
    integ = section("contact: integration, tangent")
    resid = section("contact: integration, residual")
    assembly = section("assembly")
    solve = section("linear solve")
    wall = float(re.search(r"Total wallclock time elapsed since start\s*\|\s*([\d.e+-]+)s", screen).group(1))
    dofs = int(re.search(r"DoFs: (\d+)", screen).group(1))
    lines = open(os.path.join(d, "statistics")).read().split("\n")
    names = lines[0].split()
    last = dict(zip(names, map(float, lines[-2].split() if lines[-1] == "" else lines[-1].split())))
    spread = (last["contact1_max_pressure"] - last["contact1_min_pressure"]) / last["contact1_max_pressure"]
    rows.append(dict(n=n, faces=n * n, dofs=dofs, search=search[1] / max(search[0], 1),
                     integ=integ[1] / max(integ[0], 1), calls=integ[0],
                     resid=resid[1] / max(resid[0], 1), resid_calls=resid[0],
                     bulk=(assembly[1] - integ[1]) / max(assembly[0], 1), solve=solve[1], wall=wall,
                     spread=spread, newton=int(last["newton_iterations"])))

with open(os.path.join(here, "results.md"), "w") as out:
    out.write("| slave faces | unknowns | search s/call | contact residual + tangent s/call | calls | "
              "contact residual only s/call | calls | bulk assembly s/call | solve s | wall s | "
              "pressure spread |\n")
    out.write("|---|---|---|---|---|---|---|---|---|---|---|\n")
    for r in rows:
        out.write(f"| {r['faces']} | {r['dofs']} | {r['search']:.4f} | {r['integ']:.4f} | {r['calls']} | "
                  f"{r['resid']:.4f} | {r['resid_calls']} | "
                  f"{r['bulk']:.3f} | {r['solve']:.1f} | {r['wall']:.1f} | {r['spread']:.1e} |\n")
print(open(os.path.join(here, "results.md")).read())
try:
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
except ImportError:
    sys.exit(0)
f = [r["faces"] for r in rows]
plt.figure(figsize=(6, 4.5))
plt.loglog(f, [r["integ"] for r in rows], "o-", label="contact residual + consistent tangent (per Newton iteration)")
plt.loglog(f, [r["resid"] for r in rows], "v-", label="contact residual only (per line-search trial)")
plt.loglog(f, [r["search"] for r in rows], "s-", label="search (per load step)")
plt.loglog(f, [r["bulk"] for r in rows], "^-", label="bulk assembly (residual + tangent)")
if len(f) > 1:
    plt.loglog(f, [rows[-1]["integ"] * x / f[-1] for x in f], "k:", label="linear in faces")
plt.xlabel("slave faces")
plt.ylabel("wall time per call [s]")
plt.legend(fontsize=7)
plt.grid(True, which="both", alpha=0.3)
plt.tight_layout()
plt.savefig(os.path.join(here, "scaling.png"), dpi=120)
print("wrote scaling.png")
