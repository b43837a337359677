#!/usr/bin/env python3
"""Table of the runs of run.sh (results.md): energy error against time step
and run time for the redistributed and the consistent contact mass."""
import pathlib
import re
import sys

here = pathlib.Path(sys.argv[1] if len(sys.argv) > 1 else pathlib.Path(__file__).parent)
K0, DURATION = 20.0, 2e-3


def table(path):
    rows = [l.split() for l in open(path) if l.strip() and not l.startswith('#')]
    head = rows[0]
    data = [list(map(float, r)) for r in rows[1:]]
    return {h: [r[i] for r in data] for i, h in enumerate(head)}


def runs():
    for mass in ["redistributed", "consistent"]:
        for dt in ["4e-5", "2e-5", "1e-5", "5e-6", "2.5e-6"]:
            run = here / "runs" / f"{mass}_{dt}"
            if (run / "statistics").exists():
                yield mass, float(dt), run


def summary(run):
    t = table(run / "statistics")
    active = t["contact1_active_nodes"]
    closings = sum(1 for a, b in zip(active, active[1:]) if a == 0 and b > 0)
    openings = [t["time"][i - 1] for i in range(1, len(active)) if active[i - 1] > 0 and active[i] == 0]
    first = next((t["time"][i - 1] for i in range(1, len(active)) if active[i] > 0), None)
    log = (run / "log.txt").read_text() if (run / "log.txt").exists() else ""
    m = re.search(r"revision\s+([0-9a-f]+)", log)
    return {
        "commit": m.group(1) if m else "?",
        "end": -t["energy_residual"][-1] / K0,
        "worst": max(abs(r) for r in t["energy_residual"]) / K0,
        "closings": closings,
        "duration": (openings[0] - first) / DURATION if openings and first is not None else float("nan"),
        "newton": int(sum(t["newton_iterations"])),
        "wall": t["wall_time"][-1],
        "steps": len(t["time"]) - 1,
    }


lines = ["# An elastic impact: energy error against the time step", "",
         "`prm/bar_impact.prm` (two bars of 20 Q2 cells, one at rest, one at 2 m/s; 1-D theory: contact for "
         "2L/c = 2 ms, no energy lost), the trapezoidal rule, 2 ranks, from `run.sh`; "
         "the commit each run ran is in its log.txt. Energy error: −energy_residual = "
         "K + Ψ − K₀ (W_ext = 0), over K₀ = 20 J.", "",
         "| contact mass | dt [µs] | commit | energy error at the end / K₀ | largest / K₀ | "
         "contact closings | duration / (2L/c) | steps | Newton iterations | wall [s] |",
         "|---|---|---|---|---|---|---|---|---|---|"]
for mass, dt, run in runs():
    s = summary(run)
    lines.append(f"| {mass} | {dt * 1e6:g} | {s['commit']} | {s['end']:.4e} | {s['worst']:.4e} | "
                 f"{s['closings']} | {s['duration']:.4f} | {s['steps']} | {s['newton']} | {s['wall']:.1f} |")
(here / "results.md").write_text("\n".join(lines) + "\n")
print("\n".join(lines))
