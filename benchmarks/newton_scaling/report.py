#!/usr/bin/env python3
"""Builds results.md (table), scaling.png (time per Newton iteration against
the unknowns) and per_unknown.png (µs·core per unknown per Newton
iteration, now against 2026-11-21) from runs/*/statistics of
benchmarks/newton_scaling/run.sh and the runs of 2026-11-21 kept in
runs/2026-11-21/ (Amesos MUMPS, a new factorisation per solve; AMG
hierarchy rebuilt per iteration in both)."""
import glob
import os
import re
import sys

here = sys.argv[1] if len(sys.argv) > 1 else os.path.dirname(os.path.abspath(__file__))
def read_run(run, series):
    """One row of the table from a run directory, None if it has no step."""
    m = re.match(r"(.*)-r(\d+)-np(\d+)$", os.path.basename(run))
    solver, refine, np_ = m.group(1), int(m.group(2)), int(m.group(3))
    lines = open(os.path.join(run, "statistics")).read().split("\n")
    names = lines[0].split()
    last = dict(zip(names, map(float, lines[-2].split())))
    if int(last["step"]) < 1:
        return None
    screen = open(os.path.join(run, "screen.txt")).read()
    dofs = int(re.search(r"DoFs: (\d+)", screen).group(1))
    newton = int(last["newton_iterations"])
    # tangent assemblies = Newton iterations (the converged state is checked
    # with the line-search residual, which is counted in assembly_time too)
    rss = int(open(os.path.join(run, "max_rss_kb")).read().split()[-1]) / 1024 ** 2
    assembly = last["assembly_time"] / newton
    solve = last["solve_time"] / newton
    return dict(series=series, solver=solver, refine=refine, np=np_,
                dofs=dofs, newton=newton, linear=int(last["linear_iterations"]),
                assembly=assembly, solve=solve, wall=last["wall_time"],
                rss=rss, force=abs(last["F5_z"]),
                per_dof=1e6 * (assembly + solve) * np_ / dofs)


rows = []
for series, folder in [("2026-11-21", os.path.join(here, "runs", "2026-11-21")),
                       ("current", os.path.join(here, "runs"))]:
    for stat in sorted(glob.glob(os.path.join(folder, "*", "statistics"))):
        row = read_run(os.path.dirname(stat), series)
        if row:
            rows.append(row)

rows.sort(key=lambda r: (r["series"], r["solver"], r["np"], r["dofs"]))
with open(os.path.join(here, "results.md"), "w") as f:
    f.write("| runs of | solver | ranks | DoFs | Newton its | linear its / Newton | "
            "assembly s / Newton | solve s / Newton | solve µs·core / DoF | "
            "Newton iteration µs·core / DoF | total wall s | "
            "max RSS per rank GiB | top force F5_z |\n")
    f.write("|---|---|---|---|---|---|---|---|---|---|---|---|---|\n")
    for r in rows:
        f.write(f"| {r['series']} | {r['solver']} | {r['np']} | {r['dofs']} | "
                f"{r['newton']} | {r['linear'] / r['newton']:.1f} | "
                f"{r['assembly']:.3g} | {r['solve']:.3g} | "
                f"{1e6 * r['solve'] * r['np'] / r['dofs']:.3g} | "
                f"{r['per_dof']:.3g} | {r['wall']:.3g} | {r['rss']:.2f} | "
                f"{r['force']:.8g} |\n")
print(open(os.path.join(here, "results.md")).read())

try:
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
except ImportError:
    print("matplotlib missing (scripts/install-deps.sh --plots): no plot")
    sys.exit(0)


def finish(fig, ax, ylabel, title, file_name):
    """Labels, grid and legend of a plot against the unknowns; saves it."""
    ax.set_xlabel("unknowns")
    ax.set_ylabel(ylabel)
    ax.set_title(title)
    ax.grid(True, which="both", lw=0.3)
    ax.legend(fontsize=7)
    fig.tight_layout()
    fig.savefig(os.path.join(here, file_name), dpi=120)


now = [r for r in rows if r["series"] == "current"] or rows
fig, ax = plt.subplots(figsize=(7, 5))
for (solver, np_), marker in zip(
        [("cg-amg", 1), ("cg-amg", 2), ("direct", 1), ("direct", 2)], "osD^"):
    sel = [r for r in now if r["solver"] == solver and r["np"] == np_]
    if not sel:
        continue
    n = [r["dofs"] for r in sel]
    ax.loglog(n, [r["solve"] for r in sel], "-" + marker, label=f"solve, {solver}, {np_} rank(s)")
    ax.loglog(n, [r["assembly"] for r in sel], ":" + marker, label=f"assembly, {solver}, {np_} rank(s)")
n0 = min(r["dofs"] for r in now)
n1 = max(r["dofs"] for r in now)
ref = [r for r in now if r["solver"] == "cg-amg" and r["np"] == 1 and r["dofs"] == n0]
if ref:
    ax.loglog([n0, n1], [ref[0]["solve"], ref[0]["solve"] * n1 / n0], "k--", lw=0.8, label="O(N)")
finish(fig, ax, "wall time per Newton iteration [s]",
       "Newton iteration cost, Q2 finite-strain column", "scaling.png")

# µs·core per unknown per Newton iteration (assembly + linear solve), the
# runs of 2026-11-21 dashed, the current ones solid.
fig, ax = plt.subplots(figsize=(7, 5))
colours = {("cg-amg", 1): "C0", ("cg-amg", 2): "C1", ("direct", 1): "C2",
           ("direct", 2): "C3"}
for (solver, np_), colour in colours.items():
    for series, style in [("2026-11-21", "--"), ("current", "-")]:
        sel = [r for r in rows if r["series"] == series and
               r["solver"] == solver and r["np"] == np_]
        if sel:
            ax.semilogx([r["dofs"] for r in sel], [r["per_dof"] for r in sel],
                        style + "o", color=colour,
                        label=f"{solver}, {np_} rank(s), {series}")
ax.set_yscale("log")
finish(fig, ax, "µs·core per unknown per Newton iteration",
       "Cost per unknown, Q2 finite-strain column (assembly + solve)",
       "per_unknown.png")
