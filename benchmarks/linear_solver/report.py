"""Table of the linear_solver runs: per scene and variant the unknowns,
Newton and linear iterations, the linear solve's time per Newton iteration,
the whole run's time per iteration, peak memory, MUMPS's work (analyses,
factorisations) and the scene's last force, which has to be the same for
every variant (the same answer at another cost). Writes results.md."""
import os
import re
import sys

here = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, os.path.join(here, ".."))
from runs_io import read_statistics, wall_time  # noqa: E402

force_columns = {"box_compression": "F5_z", "two_bodies": "F2_z",
                 "sent_coarse": "F2_y", "ductile_notch": "F2_y",
                 "hertz_sphere": "F2_z"}
order = ["amesos-mumps", "amesos-klu", "mumps-pord", "mumps-metis",
         "mumps-metis-ldlt", "mumps-metis-reuse", "gmres-amg"]


def find(pattern, text, default="-"):
    m = re.search(pattern, text)
    return m.group(1) if m else default


def row(scene, variant, run):
    screen = open(os.path.join(run, "screen.txt")).read()
    unknowns = find(r"DoFs: (\d+)", screen)
    memory = find(r"peak memory (\d+) KB", screen)
    memory = f"{int(memory) / 1024:.0f}" if memory != "-" else "-"
    mumps = re.search(r"MUMPS \([^)]*\): (\d+) analyses "
                      r"(?:\(\d+ on all ranks\) )?[\d.e+-]+ s, (\d+) "
                      r"factorisations ([\d.e+-]+) s, (\d+) solves", screen)
    work = (f"{mumps.group(1)} / {mumps.group(2)} / {mumps.group(4)}"
            if mumps else "-")
    stats = os.path.join(run, "statistics")
    if not os.path.exists(stats) or wall_time(os.path.join(run, "screen.txt")) is None:
        return f"| {scene} | {variant} | {unknowns} | failed | | | | | | | |"
    rows = read_statistics(stats)
    last = rows[-1]
    its = sum(r["newton_iterations"] for r in rows)
    lin = sum(r["linear_iterations"] for r in rows)
    per = lambda x: 1e3 * x / its if its else float("nan")  # noqa: E731
    column = force_columns[scene]
    return (f"| {scene} | {variant} | {unknowns} | {int(last['step'])} | "
            f"{its:.0f} | {lin:.0f} | {per(last['solve_time']):.0f} | "
            f"{per(last['wall_time']):.0f} | {memory} | {work} | "
            f"{column} = {last[column]:.8g} |")


lines = ["| scene | variant | unknowns | steps | Newton its | linear its | "
         "linear solve [ms/it] | whole run [ms/it] | peak memory [MB/rank] | "
         "MUMPS analyses / factorisations / solves | last force |",
         "|---|---|---|---|---|---|---|---|---|---|---|"]
runs = os.path.join(here, "runs")
for scene in force_columns:
    for variant in order:
        run = os.path.join(runs, scene, variant)
        if os.path.exists(os.path.join(run, "screen.txt")):
            lines.append(row(scene, variant, run))
open(os.path.join(here, "results.md"), "w").write("\n".join(lines) + "\n")
print("\n".join(lines))
