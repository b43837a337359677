#!/usr/bin/env python3
"""results.md of run.sh: per run the Newton iterations per step and the
assembly and linear-solve time per Newton iteration."""
import pathlib
import re
import sys

here = pathlib.Path(sys.argv[1] if len(sys.argv) > 1 else pathlib.Path(__file__).parent)


def table(path):
    rows = [l.split() for l in open(path) if l.strip() and not l.startswith('#')]
    return {h: [float(r[i]) for r in rows[1:]] for i, h in enumerate(rows[0])}


lines = ["# The cost of a dynamic step", "",
         "`scene.prm.in`: a bar of 160 × 4 × 4 Q2 cells on 2 ranks, 20 steps of 10 µs, from "
         "`run.sh`; the commit each run ran is in its log.txt. Times are cumulative wall "
         "times of the statistics (assembly with its line-search passes, linear solve).", "",
         "| time integration | commit | unknowns | Newton iterations per step | assembly per "
         "iteration [ms] | linear solve per iteration [ms] | wall [s] | reaction at x = L at "
         "the end [N] |",
         "|---|---|---|---|---|---|---|---|"]
for mode in ["Bossak", "quasi-static"]:
    run = here / "runs" / mode
    if not (run / "statistics").exists():
        continue
    t = table(run / "statistics")
    log = (run / "log.txt").read_text() if (run / "log.txt").exists() else ""
    rev = re.search(r"revision\s+([0-9a-f]+)", log)
    dofs = re.search(r"DoFs:\s+(\d+)", log)
    steps = len(t["time"]) - 1
    newton = sum(t["newton_iterations"])
    lines.append(f"| {mode} | {rev.group(1) if rev else '?'} | {dofs.group(1) if dofs else '?'} | "
                 f"{newton / steps:.2f} | {1e3 * t['assembly_time'][-1] / newton:.0f} | "
                 f"{1e3 * t['solve_time'][-1] / newton:.0f} | {t['wall_time'][-1]:.1f} | "
                 f"{t['F1_x'][-1]:.5g} |")
(here / "results.md").write_text("\n".join(lines) + "\n")
print("\n".join(lines))
