#!/usr/bin/env python3
"""results.md and hertz.png of benchmarks/contact/hertz: fitted contact
half-width a and peak pressure p0 against Hertz, per mesh and basis, with
run times. Usage: report.py DIR"""
import glob
import math
import os
import re
import sys

import numpy as np

here = sys.argv[1] if len(sys.argv) > 1 else os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", ".."))
from runs_io import read_statistics, wall_time  # noqa: E402

E, nu, R = 1e9, 0.3, 1.0


def e_star(stiff):
    """Plane-strain contact modulus: 1/E* = (1 - nu^2) (1/E_1 + 1/E_2); the
    indenter E_2 = E, or 3 E in the runs *_stiff."""
    E2 = 3 * E if stiff else E
    return 1 / ((1 - nu ** 2) * (1 / E + 1 / E2))


def columns(two_d):
    """Columns of the contact node table: x (current) and pressure; the
    slab's has X Y Z x y z pressure ..., the plane's X Y x y pressure ..."""
    return (2, 4) if two_d else (3, 6)


def fit(nodes, a_hertz, two_d):
    """a, p0 from p^2 = p0^2 - (p0/a)^2 x^2 over the active nodes at
    x <= 0.8 a (Hertz): the nodes near the edge carry the discretisation
    of the square-root edge."""
    ix, ip = columns(two_d)
    x, p = nodes[:, ix], nodes[:, ip]
    active = p > 0
    x, p = x[active], p[active]
    sel = x <= 0.8 * a_hertz
    A = np.vstack([np.ones(sel.sum()), x[sel] ** 2]).T
    c, *_ = np.linalg.lstsq(A, p[sel] ** 2, rcond=None)
    return math.sqrt(-c[0] / c[1]), math.sqrt(c[0])


rows = []
for d in sorted(glob.glob(os.path.join(here, "runs", "h*-*"))):
    m = re.match(r"h(\d+)-(\w+)$", os.path.basename(d))
    if not m or not os.path.exists(os.path.join(d, "statistics")):
        continue
    wall = wall_time(os.path.join(d, "screen.txt"))
    if wall is None:
        continue  # still running or failed
    table = read_statistics(os.path.join(d, "statistics"))
    last = table[-1]
    step = int(last["step"])
    nodes = np.loadtxt(os.path.join(d, f"contact1_{step:05d}.txt"), skiprows=1)
    two_d = "_2d" in m.group(2)
    E_star = e_star("_stiff" in m.group(2))
    # The slab is one element thick; the plane gives forces per unit
    # thickness.
    thickness = 1.0 if two_d else nodes[:, 2].max()
    P = 2 * abs(last["F2_y"]) / thickness
    a_h = math.sqrt(4 * P * R / (math.pi * E_star))
    p0_h = 2 * P / (math.pi * a_h)
    a, p0 = fit(nodes, a_h, two_d)
    ix, ip = columns(two_d)
    centre = nodes[(nodes[:, ix] < 1e-12) & (nodes[:, ip] > 0), ip].max()
    # The nodal pressures against Hertz's at their positions, x <= a/2:
    # the amplitude of the vertex/mid-side alternation.
    face = nodes if two_d else nodes[nodes[:, 2] < 1e-12]
    inner = face[(face[:, ip] > 0) & (face[:, ix] <= 0.5 * a_h)]
    hertz = p0_h * np.sqrt(1 - (inner[:, ix] / a_h) ** 2)
    wiggle = np.abs(inner[:, ip] / hertz - 1).max()
    screen = open(os.path.join(d, "screen.txt")).read()
    dofs = int(re.search(r"DoFs: (\d+)", screen).group(1))
    newton = int(sum(row["newton_iterations"] for row in table))
    rows.append(dict(ratio=int(m.group(1)), basis=m.group(2), dofs=dofs, P=P, a=a, a_h=a_h,
                     p0=p0, p0_h=p0_h, centre=centre, wiggle=wiggle, wall=wall, newton=newton,
                     pen=last["contact1_max_penetration"]))

rows.sort(key=lambda r: (r["basis"], r["ratio"]))
with open(os.path.join(here, "results.md"), "w") as out:
    out.write("| basis | h | unknowns | P [N/m] | a fit / Hertz - 1 | p0 fit / Hertz - 1 | "
              "centre node p / p0 Hertz - 1 | max nodal p / p Hertz - 1, x <= a/2 | Newton its | "
              "max penetration [m] | wall [s] |\n")
    out.write("|---|---|---|---|---|---|---|---|---|---|---|\n")
    for r in rows:
        out.write(f"| {r['basis']} | a/{r['ratio']} | {r['dofs']} | {r['P']:.5g} | "
                  f"{r['a'] / r['a_h'] - 1:+.2e} | {r['p0'] / r['p0_h'] - 1:+.2e} | "
                  f"{r['centre'] / r['p0_h'] - 1:+.2e} | {r['wiggle']:.2e} | {r['newton']} | {r['pen']:.1e} | {r['wall']:.1f} |\n")
print(open(os.path.join(here, "results.md")).read())
try:
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
except ImportError:
    sys.exit(0)
fig, (l, r) = plt.subplots(1, 2, figsize=(11, 4.3))
for basis, mk in (("dual", "o"), ("standard", "s"), ("dual_2d", "^"), ("standard_2d", "v"),
                  ("dual_2d_curved", "D")):
    sub = [x for x in rows if x["basis"] == basis]
    if sub:
        l.loglog([x["wall"] for x in sub], [abs(x["a"] / x["a_h"] - 1) for x in sub], mk + "-", label=f"a, {basis}")
        l.loglog([x["wall"] for x in sub], [abs(x["p0"] / x["p0_h"] - 1) for x in sub], mk + "--", label=f"p0, {basis}")
l.set_xlabel("wall time [s]")
l.set_ylabel("relative error against Hertz")
l.grid(True, which="both", alpha=0.3)
l.legend(fontsize=7)
for x in rows:
    if (x["basis"] in ("dual", "dual_2d_curved") and x["ratio"] in (4, 8)) or \
            (x["basis"] == "standard" and x["ratio"] == 8):
        two_d = "_2d" in x["basis"]
        d = os.path.join(here, "runs", f"h{x['ratio']}-{x['basis']}")
        step = int(read_statistics(os.path.join(d, "statistics"))[-1]["step"])
        n = np.loadtxt(os.path.join(d, f"contact1_{step:05d}.txt"), skiprows=1)
        ix, ip = columns(two_d)
        if not two_d:
            n = n[n[:, 2] < 1e-12]  # one face of the slab
        n = n[n[:, ip] > 0]
        n = n[np.argsort(n[:, ix])]
        r.plot(n[:, ix] / x["a_h"], n[:, ip] / x["p0_h"], ".-", label=f"{x['basis']} h = a/{x['ratio']}")
xs = np.linspace(0, 1, 200)
r.plot(xs, np.sqrt(1 - xs ** 2), "k-", lw=2, label="Hertz")
r.set_xlabel("x / a (Hertz)")
r.set_ylabel("nodal pressure / p0 (Hertz)")
r.legend(fontsize=7)
r.grid(True, alpha=0.3)
fig.tight_layout()
fig.savefig(os.path.join(here, "hertz.png"), dpi=120)
print("wrote hertz.png")
