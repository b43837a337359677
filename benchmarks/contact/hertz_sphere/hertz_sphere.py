"""Hertz point contact of two equal elastic bodies (sphere R on a flat):
closed forms and the evaluation of a run, shared by report.py here and
usable on any run of prm/hertz_sphere.prm:
    /usr/bin/python3 hertz_sphere.py RESULTS_DIR
prints per step the load P, the contact radius a and peak pressure p0
(least-squares fit of p^2 = p0^2 (1 - r^2/a^2) to the nodal pressures at
r <= 0.8 a) and the approach of the two axis probes, each against Hertz.

Approach: the probes sit on the axis at depth d below (probe 1) and height d
above (probe 2) the first contact point; the surface points between them
coincide, so their approach is the compression of the two columns,
delta_d = 2 integral_0^d -eps_z dz, with the axis stresses of the Hertz
field in a half-space (Johnson 1985, eq. 3.45)
    sigma_z = -p0 / (1 + z^2/a^2),
    sigma_r = sigma_t = p0 [-(1 + nu)(1 - (z/a) atan(a/z)) + 1 / (2 (1 + z^2/a^2))],
    eps_z = (sigma_z - 2 nu sigma_r) / E.
"""
import math
import os
import sys

import numpy as np

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", ".."))
from runs_io import read_statistics  # noqa: E402


def axial_compression(d_over_a, nu, n=200):
    """integral_0^{d/a} -E eps_z / p0 d(z/a), by Gauss-Legendre in
    t = atan(z/a)."""
    t, w = np.polynomial.legendre.leggauss(n)
    top = math.atan(d_over_a)
    t = 0.5 * top * (t + 1)
    w = 0.5 * top * w
    z = np.tan(t)
    with np.errstate(divide="ignore"):
        sr = -(1 + nu) * (1 - z * np.arctan(1 / z)) + 0.5 / (1 + z * z)
    sz = -1 / (1 + z * z)
    return float(np.sum(-(sz - 2 * nu * sr) / np.cos(t) ** 2 * w))


def hertz(P, R, E, nu, d):
    """a, p0 and the approach of the axis points at depth d of two equal
    bodies carrying the load P."""
    E_star = E / (2 * (1 - nu ** 2))
    a = (3 * P * R / (4 * E_star)) ** (1 / 3)
    p0 = 3 * P / (2 * math.pi * a ** 2)
    return a, p0, 2 * p0 * a / E * axial_compression(d / a, nu)


def fit(nodes, a_hertz):
    """a, p0 from p^2 = p0^2 - (p0/a)^2 r^2 over the active nodes at
    r <= 0.8 a (Hertz): the nodes near the edge carry the discretisation
    of the square-root edge. nodes: columns of contact1_<step>.txt."""
    r = np.hypot(nodes[:, 3], nodes[:, 4])
    p = nodes[:, 6]
    sel = (p > 0) & (r <= 0.8 * a_hertz)
    A = np.vstack([np.ones(sel.sum()), r[sel] ** 2]).T
    c, *_ = np.linalg.lstsq(A, p[sel] ** 2, rcond=None)
    return math.sqrt(-c[0] / c[1]), math.sqrt(c[0])


def evaluate(directory, R=1.0, E=1e9, nu=0.3, d=0.02):
    """Per step of a run: P, a, p0, approach and their Hertz values."""
    rows = []
    for s in read_statistics(os.path.join(directory, "statistics")):
        step = int(s["step"])
        path = os.path.join(directory, f"contact1_{step:05d}.txt")
        if step == 0 or not os.path.exists(path):
            continue
        P = 4 * abs(s["F2_z"])  # quarter model
        a_h, p0_h, approach_h = hertz(P, R, E, nu, d)
        a, p0 = fit(np.loadtxt(path, skiprows=1), a_h)
        rows.append(dict(step=step, P=P, a=a, a_h=a_h, p0=p0, p0_h=p0_h,
                         approach=s["probe1_u_z"] - s["probe2_u_z"], approach_h=approach_h,
                         penetration=s["contact1_max_penetration"],
                         newton=int(s["newton_iterations"])))
    return rows


if __name__ == "__main__":
    print(f"{'step':>4} {'P [N]':>10} {'a/a_H-1':>10} {'p0/p0_H-1':>10} {'approach [m]':>13} "
          f"{'/Hertz-1':>10}")
    for r in evaluate(sys.argv[1]):
        print(f"{r['step']:4d} {r['P']:10.4g} {r['a'] / r['a_h'] - 1:+10.2e} "
              f"{r['p0'] / r['p0_h'] - 1:+10.2e} {r['approach']:13.5e} "
              f"{r['approach'] / r['approach_h'] - 1:+10.2e}")
