"""Table of the iterative_solver runs: per case, refinement and variant the
unknowns, Newton iterations, Krylov iterations per linear solve (mean and
largest, from the runs' 'linear iterations' lines), the linear solve's time
per Newton iteration and the last force, which must agree between the
variants of a case and refinement. Writes results.md."""
import os
import re
import sys

here = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, os.path.join(here, ".."))
from runs_io import find, read_statistics, wall_time  # noqa: E402

force_columns = {"strip_elastic": "F2_y", "strip": "F2_y",
                 "ductile_notch_2d": "F2_y", "hertz_cylinder_2d": "F2_y",
                 "two_bodies": "F2_z", "two_bodies_k3": "F2_z",
                 "two_bodies_k4": "F2_z"}
order = ["direct", "gmres-amg", "gmres-amg-sgs", "gmres-amg-sgs-r400",
         "gmres-amg-pf-direct", "gmres-amg-elim", "gmres-amg-pb",
         "gmres-amg-sgs-pb", "gmres-amg-sgs-r400-pb", "gmres-amg-pf-direct-pb",
         "gmres-amg-elim-pb"]


def row(case, refinement, variant, run):
    screen_path = os.path.join(run, "screen.txt")
    screen = open(screen_path).read()
    unknowns = find(r"DoFs: (\d+)", screen, "-")
    stats = os.path.join(run, "statistics")
    if not os.path.exists(stats) or wall_time(screen_path) is None:
        return f"| {case} | {refinement} | {variant} | {unknowns} | failed | | | |"
    rows = read_statistics(stats)
    last = rows[-1]
    newton = sum(r["newton_iterations"] for r in rows)
    krylov = [int(k) for k in re.findall(r"linear iterations (\d+)", screen)]
    mean = sum(krylov) / len(krylov) if krylov else float("nan")
    solve = 1e3 * last["solve_time"] / newton if newton else float("nan")
    column = force_columns[case]
    return (f"| {case} | {refinement} | {variant} | {unknowns} | "
            f"{newton:.0f} | {mean:.1f} / {max(krylov) if krylov else '-'} | "
            f"{solve:.0f} | {last[column]:.8g} |")


lines = ["| case | r | variant | unknowns | Newton its | Krylov its per "
         "solve: mean / largest | linear solve [ms per Newton it] | "
         "last force |",
         "|---|---|---|---|---|---|---|---|"]
runs = os.path.join(here, "runs")
for case in force_columns:
    for refinement in range(6):
        for variant in order + [v + "-np2" for v in order]:
            run = os.path.join(runs, case, f"r{refinement}-{variant}")
            if os.path.exists(os.path.join(run, "screen.txt")):
                lines.append(row(case, refinement, variant, run))
open(os.path.join(here, "results.md"), "w").write("\n".join(lines) + "\n")
print("\n".join(lines))
