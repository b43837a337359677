#!/usr/bin/env python3
"""results.md and hertz_sphere.png of benchmarks/contact/hertz_sphere: per
mesh the errors of the contact radius a, the peak pressure p0 and the
approach of the axis probes against Hertz at the last load step, with run
times, and the force-approach curves. Usage: report.py DIR"""
import glob
import math
import os
import re
import sys

from hertz_sphere import evaluate, hertz

here = sys.argv[1] if len(sys.argv) > 1 else os.path.dirname(os.path.abspath(__file__))
runs = []
for d in sorted(glob.glob(os.path.join(here, "runs", "h*-w*"))):
    m = re.match(r"h(\d+)-w([\d.]+)(-curved)?$", os.path.basename(d))
    screen = os.path.join(d, "screen.txt")
    if not m or not os.path.exists(screen) or "Total wallclock" not in open(screen).read():
        continue  # still running or failed
    text = open(screen).read()
    rows = evaluate(d)
    runs.append(dict(ratio=int(m.group(1)), width=float(m.group(2)), rows=rows,
                     surface="sphere" if m.group(3) else "polygon",
                     dofs=int(re.search(r"DoFs: (\d+)", text).group(1)),
                     wall=float(re.search(r"Total wallclock time elapsed since start\s*\|\s*([\d.e+-]+)s",
                                          text).group(1)),
                     newton=sum(r["newton"] for r in rows)))
runs.sort(key=lambda r: (r["surface"], r["width"], r["ratio"]))


def err(r, key):
    return r[key] / r[key + "_h"] - 1


with open(os.path.join(here, "results.md"), "w") as out:
    out.write("Last load step (indenter's top moved down by 0.1 mm); errors relative to Hertz "
              "for the load P the run carries.\n\n")
    out.write("| surface | h | bodies | unknowns | P [N] | approach error | a error | p0 error | "
              "Newton its (4 steps) | max penetration [m] | wall [s] |\n")
    out.write("|---|---|---|---|---|---|---|---|---|---|---|\n")
    for run in runs:
        r = run["rows"][-1]
        out.write(f"| {run['surface']} | a/{run['ratio']} | {run['width'] / 0.01:.0f} a | {run['dofs']} | {r['P']:.5g} | "
                  f"{err(r, 'approach'):+.2e} | {err(r, 'a'):+.2e} | {err(r, 'p0'):+.2e} | "
                  f"{run['newton']} | {max(x['penetration'] for x in run['rows']):.1e} | "
                  f"{run['wall']:.0f} |\n")
    out.write("\nEvery load step (force-approach curve):\n\n")
    out.write("| surface | h | bodies | step | P [N] | approach [m] | Hertz approach [m] | error |\n")
    out.write("|---|---|---|---|---|---|---|---|\n")
    for run in runs:
        for r in run["rows"]:
            out.write(f"| {run['surface']} | a/{run['ratio']} | {run['width'] / 0.01:.0f} a | {r['step']} | {r['P']:.5g} | "
                      f"{r['approach']:.5e} | {r['approach_h']:.5e} | {err(r, 'approach'):+.2e} |\n")
print(open(os.path.join(here, "results.md")).read())
try:
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
except ImportError:
    sys.exit(0)
fig, (left, right) = plt.subplots(1, 2, figsize=(11, 4.3))
main = [r for r in runs if abs(r["width"] - 0.2) < 1e-12 and r["surface"] == "polygon"]
curved = [r for r in runs if r["surface"] == "sphere"]
for key, mk, label in (("approach", "o-", "approach at 2a"), ("a", "s--", "contact radius a"),
                       ("p0", "^:", "peak pressure p0")):
    left.loglog([r["wall"] for r in main], [abs(err(r["rows"][-1], key)) for r in main], mk, label=label)
for key, mk, label in (("approach", "o-", "approach, sphere given"), ("p0", "^:", "p0, sphere given")):
    left.loglog([r["wall"] for r in curved], [abs(err(r["rows"][-1], key)) for r in curved], mk,
                color="C3" if key == "p0" else "C4", label=label)
for r in main:
    left.annotate(f"a/{r['ratio']}", (r["wall"], abs(err(r["rows"][-1], "approach"))),
                  textcoords="offset points", xytext=(4, 4), fontsize=8)
left.set_xlabel("wall time, 2 ranks [s]")
left.set_ylabel("relative error against Hertz (last step)")
left.legend()
left.grid(True, which="both", alpha=0.3)
if main:
    Pmax = max(r["rows"][-1]["P"] for r in main)
    P = [0.0] + [Pmax * (i / 100) ** 3 for i in range(1, 101)]
    right.plot([hertz(p, 1.0, 1e9, 0.3, 0.02)[2] * 1e6 if p > 0 else 0.0 for p in P], P, "k-",
               label="Hertz")
for r in main:
    right.plot([0] + [x["approach"] * 1e6 for x in r["rows"]], [0] + [x["P"] for x in r["rows"]],
               "o--", ms=4, label=f"h = a/{r['ratio']}")
right.set_xlabel("approach of the axis points at 2a [µm]")
right.set_ylabel("load P [N]")
right.legend()
right.grid(True, alpha=0.3)
fig.tight_layout()
fig.savefig(os.path.join(here, "hertz_sphere.png"), dpi=120)
