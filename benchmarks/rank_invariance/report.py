#!/usr/bin/python3
"""Rank invariance of the shipped scenes (run.sh): per scene the steps,
unknowns, Newton iterations and wall time on 1, 2 and 3 ranks, and the
largest difference of the 1- and 3-rank statistics from the 2-rank ones
(every column but timings and iteration counts, in units of the column's
scale: tests/checkpoint/compare_statistics.py). Writes results.md; exits 1
when a difference exceeds its tolerance (1e-6; contact pressures 1e-5)."""
import os
import re
import sys

here = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, os.path.join(here, ".."))
sys.path.insert(0, os.path.join(here, "..", "..", "tests", "checkpoint"))
from compare_statistics import largest_difference  # noqa: E402
from runs_io import find, read_statistics, wall_time  # noqa: E402

runs = os.path.join(here, "runs")
rows, failures = [], []
for scene in sorted(os.listdir(runs)) if os.path.isdir(runs) else []:
    def path(np, name):
        return os.path.join(runs, scene, "np%d" % np, name)
    if (not os.path.isfile(path(2, "statistics")) or
            wall_time(path(2, "screen.txt")) is None):
        continue
    stats = read_statistics(path(2, "statistics"))
    screen = open(path(2, "screen.txt")).read()
    cells = [str(len(stats) - 1), find(r"DoFs: (\d+)", screen, "-"),
             "%g" % stats[-1]["time"]]
    walls, its, diffs = [], [], []
    for np in (1, 2, 3):
        if not os.path.isfile(path(np, "statistics")):
            walls.append("-"), its.append("-")
            if np != 2:
                diffs.append("not run")
            continue
        w = wall_time(path(np, "screen.txt"))
        if w is None:
            walls.append("-"), its.append("-")
            diffs.append("not finished")
            continue
        walls.append("%.0f" % w if w else "stopped")
        its.append("%d" % sum(r["newton_iterations"]
                              for r in read_statistics(path(np, "statistics"))))
        if np == 2:
            continue
        try:
            worst, error, where = largest_difference(path(2, "statistics"),
                                                     path(np, "statistics"))
            diffs.append("%.1e (%s)" % (error, where) if where else "0")
            if worst > 1:
                failures.append("%s on %d ranks" % (scene, np))
        except ValueError as e:
            diffs.append("**%s**" % str(e).split("\n")[0][:60])
            failures.append("%s on %d ranks" % (scene, np))
    rows.append("| `%s` | %s | %s | %s | %s | %s |" % (
        scene, " | ".join(cells), " / ".join(walls), " / ".join(its),
        diffs[0], diffs[1]))

with open(os.path.join(here, "results.md"), "w") as out:
    out.write("# Rank invariance of the shipped scenes (run.sh)\n\n")
    out.write("| scene | steps | unknowns | end time | wall [s] 1 / 2 / 3 ranks | "
              "Newton its 1 / 2 / 3 | 1 rank vs 2: largest difference | "
              "3 ranks vs 2 |\n|---|---|---|---|---|---|---|---|\n")
    out.write("\n".join(rows) + "\n\n")
    shipped = sorted(f[:-4] for f in os.listdir(os.path.join(here, "..", "..", "prm"))
                     if f.endswith(".prm"))
    done = [r.split("`")[1] for r in rows]
    missing = [s for s in shipped if s not in done]
    if missing:
        out.write("Not run yet (or not finished on 2 ranks): %s.\n\n"
                  % ", ".join("`%s`" % m for m in missing))
    out.write("Differences in units of the column's scale (the largest value "
              "of its kind in the 2-rank table); every column but timings and "
              "iteration counts. Allowed: 1e-6 (contact pressures 1e-5, "
              "tests/checkpoint/compare_statistics.py). Beyond it: %s.\n"
              % (", ".join(failures) or "none"))
print(open(os.path.join(here, "results.md")).read())
sys.exit(1 if failures else 0)
