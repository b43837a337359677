#!/usr/bin/env python3
"""results.png: the energy error of the bar impact against dt and against
run time, redistributed and consistent contact mass."""
import pathlib
import sys

import matplotlib
matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

here = pathlib.Path(sys.argv[1] if len(sys.argv) > 1 else pathlib.Path(__file__).parent)
sys.path.insert(0, str(here))
from report import runs, summary  # noqa: E402

fig, (a, b) = plt.subplots(1, 2, figsize=(10, 4))
for mass, marker in [("redistributed", "o-"), ("consistent", "s--")]:
    rows = [(dt, summary(run)) for m, dt, run in runs() if m == mass]
    if not rows:
        continue
    dts = [dt * 1e6 for dt, _ in rows]
    err = [abs(s["end"]) for _, s in rows]
    wall = [s["wall"] for _, s in rows]
    a.loglog(dts, err, marker, label=f"{mass} mass")
    b.loglog(wall, err, marker, label=f"{mass} mass")
ref = [40, 2.5]
a.loglog(ref, [2e-3 * (x / 10) ** 2 for x in ref], "k:", label="dt²")
a.set_xlabel("dt [µs]")
a.set_ylabel("|K + Ψ − K₀| / K₀ after release")
b.set_xlabel("wall time, 2 ranks [s]")
for ax in (a, b):
    ax.grid(True, which="both", alpha=0.3)
    ax.legend()
fig.suptitle("prm/bar_impact.prm: energy error of an elastic impact (trapezoidal rule)")
fig.tight_layout()
fig.savefig(here / "results.png", dpi=120)
print("wrote", here / "results.png")
