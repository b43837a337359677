#!/usr/bin/env python3
"""Table of the Lagrange and Bernstein runs of run.sh (results.md)."""
import pathlib
import re
import sys

here = pathlib.Path(sys.argv[1] if len(sys.argv) > 1 else pathlib.Path(__file__).parent)


def table(path):
    rows = [l.split() for l in open(path) if l.strip() and not l.startswith('#')]
    head = rows[0]
    data = [list(map(float, r)) for r in rows[1:]]
    return {h: [r[i] for r in data] for i, h in enumerate(head)}


lines = ["# Phase field in the Lagrange and the Bernstein basis: the coarse tearing scene", "",
         "From `run.sh` (2 ranks); the commit each run ran is in its log.txt.", "",
         "| basis | commit | largest s at a quadrature point | largest s DoF | Newton iterations | "
         "cut-backs | wall [s] | peak force [N] | end force [N] | crack energy [J] | "
         "worst balance from step 3 [% of W_ext] |",
         "|---|---|---|---|---|---|---|---|---|---|---|"]
for basis in ["Lagrange", "Bernstein"]:
    run = here / "runs" / basis
    if not (run / "statistics").exists():
        continue
    t = table(run / "statistics")
    log = (run / "log.txt").read_text() if (run / "log.txt").exists() else ""
    m = re.search(r"revision\s+([0-9a-f]+)", log)
    force = [abs(f) for f in t["F2_z"]]
    worst = max(abs(r) / w for r, w in list(zip(t["energy_residual"], t["external_work"]))[3:])
    lines.append(
        f"| {basis} | {m.group(1) if m else '?'} | {max(t['max_s_points']):.5f} | "
        f"{max(t['max_s']):.5f} | {int(sum(t['newton_iterations']))} | "
        f"{int(sum(t['cutbacks']))} | {t['wall_time'][-1]:.1f} | {max(force):.5g} | "
        f"{force[-1]:.5g} | {t['fracture_energy'][-1]:.5g} | {100 * worst:.3f} |")
(here / "results.md").write_text("\n".join(lines) + "\n")
print("\n".join(lines))
