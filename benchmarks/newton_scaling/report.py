#!/usr/bin/env python3
"""Builds results.md (table) and scaling.png (plot) from runs/*/statistics
of benchmarks/newton_scaling/run.sh."""
import glob
import os
import re
import sys

here = sys.argv[1] if len(sys.argv) > 1 else os.path.dirname(os.path.abspath(__file__))
rows = []
for stat in sorted(glob.glob(os.path.join(here, "runs", "*", "statistics"))):
    run = os.path.dirname(stat)
    m = re.match(r"(.*)-r(\d+)-np(\d+)$", os.path.basename(run))
    solver, refine, np_ = m.group(1), int(m.group(2)), int(m.group(3))
    lines = open(stat).read().split("\n")
    names = lines[0].split()
    last = dict(zip(names, map(float, lines[-2].split())))
    if int(last["step"]) < 1:
        continue
    screen = open(os.path.join(run, "screen.txt")).read()
    dofs = int(re.search(r"DoFs: (\d+)", screen).group(1))
    newton = int(last["newton_iterations"])
    # tangent assemblies = Newton iterations (the converged state is checked
    # with the line-search residual, which is counted in assembly_time too)
    rss = int(open(os.path.join(run, "max_rss_kb")).read().split()[-1]) / 1024 ** 2
    rows.append(dict(solver=solver, refine=refine, np=np_, dofs=dofs,
                     newton=newton, linear=int(last["linear_iterations"]),
                     assembly=last["assembly_time"] / newton,
                     solve=last["solve_time"] / newton,
                     wall=last["wall_time"], rss=rss))

rows.sort(key=lambda r: (r["solver"], r["np"], r["dofs"]))
with open(os.path.join(here, "results.md"), "w") as f:
    f.write("| solver | ranks | DoFs | Newton its | linear its / Newton | "
            "assembly s / Newton | solve s / Newton | solve µs·core / DoF | "
            "total wall s | max RSS per rank GiB |\n")
    f.write("|---|---|---|---|---|---|---|---|---|---|\n")
    for r in rows:
        f.write(f"| {r['solver']} | {r['np']} | {r['dofs']} | {r['newton']} | "
                f"{r['linear'] / r['newton']:.1f} | {r['assembly']:.3g} | "
                f"{r['solve']:.3g} | {1e6 * r['solve'] * r['np'] / r['dofs']:.3g} | "
                f"{r['wall']:.3g} | {r['rss']:.2f} |\n")
print(open(os.path.join(here, "results.md")).read())

try:
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
except ImportError:
    print("matplotlib missing (scripts/install-deps.sh --plots): no plot")
    sys.exit(0)
fig, ax = plt.subplots(figsize=(7, 5))
for (solver, np_), marker in zip(
        [("cg-amg", 1), ("cg-amg", 2), ("direct", 1), ("direct", 2)], "osD^"):
    sel = [r for r in rows if r["solver"] == solver and r["np"] == np_]
    if not sel:
        continue
    n = [r["dofs"] for r in sel]
    ax.loglog(n, [r["solve"] for r in sel], "-" + marker, label=f"solve, {solver}, {np_} rank(s)")
    ax.loglog(n, [r["assembly"] for r in sel], ":" + marker, label=f"assembly, {solver}, {np_} rank(s)")
n0 = min(r["dofs"] for r in rows)
n1 = max(r["dofs"] for r in rows)
ref = [r for r in rows if r["solver"] == "cg-amg" and r["np"] == 1 and r["dofs"] == n0]
if ref:
    ax.loglog([n0, n1], [ref[0]["solve"], ref[0]["solve"] * n1 / n0], "k--", lw=0.8, label="O(N)")
ax.set_xlabel("unknowns")
ax.set_ylabel("wall time per Newton iteration [s]")
ax.set_title("Newton iteration cost, Q2 finite-strain column")
ax.grid(True, which="both", lw=0.3)
ax.legend(fontsize=7)
fig.tight_layout()
fig.savefig(os.path.join(here, "scaling.png"), dpi=120)
