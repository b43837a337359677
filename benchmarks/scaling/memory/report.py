"""Table of the memory runs: per case, solver and number of ranks the
unknowns, the peak resident memory of rank 0 and of the largest rank, their
sum per unknown, the direct solver's factor entries and the wall time; and a
model per solver and number of ranks fitted to its runs:
all ranks' bytes = c * ranks + a * unknowns (+ b * factor entries for the
direct solver).
Writes results.md."""
import os
import re
import sys

here = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, os.path.join(here, "..", ".."))
from runs_io import find, wall_time  # noqa: E402

gib = 1024.0 ** 3


def least_squares(rows, rhs):
    """The coefficients x minimising |rows x - rhs| (normal equations,
    Gaussian elimination; a handful of unknowns)."""
    k = len(rows[0])
    a = [[sum(r[i] * r[j] for r in rows) for j in range(k)] +
         [sum(r[i] * y for r, y in zip(rows, rhs))] for i in range(k)]
    for i in range(k):
        pivot = max(range(i, k), key=lambda m: abs(a[m][i]))
        a[i], a[pivot] = a[pivot], a[i]
        for m in range(i + 1, k):
            factor = a[m][i] / a[i][i]
            for j in range(i, k + 1):
                a[m][j] -= factor * a[i][j]
    x = [0.0] * k
    for i in reversed(range(k)):
        x[i] = (a[i][k] - sum(a[i][j] * x[j] for j in range(i + 1, k))) / a[i][i]
    return x
lines = ["| case | solver | ranks | unknowns | rank 0 [GiB] | largest rank [GiB] "
         "| all ranks [GiB] | kB per unknown | factor entries | wall [s] |",
         "|---|---|---|---|---|---|---|---|---|---|"]
runs = os.path.join(here, "runs")
points = {}
for name in sorted(os.listdir(runs)) if os.path.isdir(runs) else []:
    screen_path = os.path.join(runs, name, "screen.txt")
    if not os.path.exists(screen_path):
        continue
    case, rest = name.split("-", 1)
    solver, np = rest.rsplit("-np", 1)
    screen = open(screen_path).read()
    unknowns = int(find(r"DoFs: (\d+)", screen, "0"))
    m = re.search(r"peak memory ([\d.]+) GiB on rank 0, ([\d.]+) GiB at most "
                  r"on one rank, ([\d.]+) GiB in all", screen)
    wall = wall_time(screen_path)
    if not m or wall is None:
        lines.append(f"| {case} | {solver} | {np} | {unknowns} | failed |"
                     " | | | | |")
        continue
    rank0, largest, total = (float(g) for g in m.groups())
    entries = float(find(r"([\d.e+]+) entries in the last factors", screen,
                         "0"))
    lines.append(f"| {case} | {solver} | {np} | {unknowns} | {rank0:.2f} | "
                 f"{largest:.2f} | {total:.2f} | "
                 f"{total * gib / 1e3 / unknowns:.1f} | "
                 f"{entries:.3g} | {wall:.0f} |")
    points.setdefault((solver, np), []).append((unknowns, entries,
                                                total * gib))

lines.append("")
for (solver, np), p in sorted(points.items()):
    # Least squares: bytes = c np + a N (+ b F for the direct solver).
    direct = solver == "direct"
    if len(p) < (3 if direct else 2):
        continue
    rows = [[float(np), float(n)] + ([f] if direct else []) for n, f, b in p]
    coef = least_squares(rows, [b for n, f, b in p])
    text = (f"- {solver}, {np} rank(s): all ranks' peak = "
            f"{coef[0] / 1e6:.0f} MB per rank + {coef[1]:.0f} bytes per "
            f"unknown")
    if direct:
        text += f" + {coef[2]:.1f} bytes per factor entry"
    lines.append(text)
open(os.path.join(here, "results.md"), "w").write("\n".join(lines) + "\n")
print("\n".join(lines))
