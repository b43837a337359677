"""Table of the iteration_cost runs: per label and scene the steps, Newton
iterations, wall time, time per Newton iteration (assembly, linear solve,
rest) and the scene's last force, which must agree between labels (the
same answer at another cost). Writes results.md next to this file."""
import os
import sys

here = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, os.path.join(here, ".."))
from runs_io import read_statistics, wall_time  # noqa: E402

# The force column each scene reports as its quantity of interest.
force_columns = {"box_compression": "F5_z", "necking_bar": "F2_x",
                 "two_bodies": "F2_z", "sent_coarse": "F2_y",
                 "ductile_notch": "F2_y"}


def row(label, scene, run):
    rows = read_statistics(os.path.join(run, "statistics"))
    last = rows[-1]
    its = sum(r["newton_iterations"] for r in rows)
    wall = wall_time(os.path.join(run, "screen.txt")) or last["wall_time"]
    per = lambda x: 1e3 * x / its if its else float("nan")  # noqa: E731
    column = force_columns.get(scene)
    force = last.get(column, float("nan")) if column else float("nan")
    return (f"| {label} | {scene} | {int(last['step'])} | {its:.0f} | "
            f"{wall:.1f} | {per(last['wall_time']):.0f} | "
            f"{per(last['assembly_time']):.0f} | {per(last['solve_time']):.0f} | "
            f"{column} = {force:.6g} |")


lines = ["| label | scene | steps | Newton its | wall [s] | ms / iteration | "
         "assembly [ms/it] | linear solve [ms/it] | last force [N or kN/mm] |",
         "|---|---|---|---|---|---|---|---|---|"]
runs = os.path.join(here, "runs")
for scene in force_columns:
    for label in sorted(os.listdir(runs)):
        run = os.path.join(runs, label, scene)
        if os.path.exists(os.path.join(run, "statistics")):
            lines.append(row(label, scene, run))
open(os.path.join(here, "results.md"), "w").write("\n".join(lines) + "\n")
print("\n".join(lines))
