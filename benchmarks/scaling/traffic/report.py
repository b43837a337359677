"""Table of the traffic runs: per case, solver and number of ranks the
unknowns and, per Newton iteration of the later steps (the difference of
the two runs to different end times), the point-to-point messages and bytes
and the collective calls and bytes of the busiest rank and their mean over
the ranks. Writes results.md."""
import os
import re
import sys

here = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, os.path.join(here, "..", ".."))
from runs_io import find, read_statistics  # noqa: E402

runs = os.path.join(here, "runs")
keys = ["p2p_messages", "p2p_bytes", "collectives", "collective_bytes"]


def counts(run):
    """Per rank: the four counts; None if the run has none."""
    path = os.path.join(run, "traffic.txt")
    if not os.path.exists(path):
        return None
    ranks = {}
    for line in open(path):
        f = line.split()
        ranks[int(f[1])] = {k: int(f[f.index(k) + 1]) for k in keys}
    return ranks


def newton(run):
    return sum(r["newton_iterations"]
               for r in read_statistics(os.path.join(run, "statistics")))


groups = {}
for name in sorted(os.listdir(runs)) if os.path.isdir(runs) else []:
    m = re.match(r"(.+)-(direct|gmres-amg)-np(\d+)-t(\d+)$", name)
    if m:
        groups.setdefault(m.groups()[:3], []).append((int(m.group(4)), name))

lines = ["| case | solver | ranks | unknowns | Newton its (difference) | "
         "p2p messages per it: busiest / mean | p2p kB per it: busiest / "
         "mean | collectives per it | collective kB per it: busiest / mean |",
         "|---|---|---|---|---|---|---|---|---|"]
for (case, solver, np), runs_of in sorted(groups.items()):
    runs_of.sort()
    if len(runs_of) < 2:
        continue
    early, late = (os.path.join(runs, n) for _, n in runs_of[:2])
    a, b = counts(early), counts(late)
    if not a or not b or len(a) != int(np) or len(b) != int(np):
        lines.append(f"| {case} | {solver} | {np} | failed | | | | | |")
        continue
    its = newton(late) - newton(early)
    unknowns = find(r"DoFs: (\d+)", open(os.path.join(late, "screen.txt")).read(),
                    "-")
    per = {r: {k: (b[r][k] - a[r][k]) / its for k in keys} for r in b}

    def pair(key, scale=1.):
        values = [per[r][key] / scale for r in per]
        return f"{max(values):.0f} / {sum(values) / len(values):.0f}"
    lines.append(f"| {case} | {solver} | {np} | {unknowns} | {its:.0f} | "
                 f"{pair('p2p_messages')} | {pair('p2p_bytes', 1e3)} | "
                 f"{max(per[r]['collectives'] for r in per):.0f} | "
                 f"{pair('collective_bytes', 1e3)} |")
open(os.path.join(here, "results.md"), "w").write("\n".join(lines) + "\n")
print("\n".join(lines))
