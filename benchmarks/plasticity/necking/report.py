"""Necking bar benchmark report: results.md and necking.png from runs/*/.

The runs model the octant x >= L/2, y >= 0, z >= 0: the bar's force is
4 F2_x, its elongation 14 mm t. Per run: the peak force and the elongation
where it occurs, and (at 11.2 mm, which every run reaches) the neck radius (hull probe at
mid-length) and the neck width at 11.2 mm: the full width at half depth of the radius
profile's dip (profile mirrored at mid-length), depth measured from the
largest radius of the probed middle 24 mm. Errors against the finest run
with the same l_p.
"""
import os
import sys

import numpy as np

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", ".."))
from runs_io import read_statistics, wall_time  # noqa: E402

R, L, E_IMP, PULL = 6.413e-3, 53.334e-3, 0.018, 14e-3
T_CMP = 0.8  # neck radius and width compared at 0.8 x 14 mm = 11.2 mm


def probe_x(n):
    return np.array([0.5 * L + k * 0.5e-3 for k in range(n)])


def profile(row):
    """Hull radius r(x) [m] at the probes of one statistics row."""
    n = sum(1 for k in row if k.startswith("probe") and k.endswith("_u_y"))
    x = probe_x(n)
    f = 1 - E_IMP * (1 - np.abs(2 * x / L - 1))
    y0 = 0.9998 * f * R
    uy = np.array([row[f"probe{k + 1}_u_y"] for k in range(n)])
    xc = x + np.array([row[f"probe{k + 1}_u_x"] for k in range(n)])
    # Mirrored at the symmetry plane x = L/2 (which stays in place).
    return (np.concatenate([L - xc[:0:-1], xc]),
            np.concatenate([(y0 + uy)[:0:-1], y0 + uy]))


def neck_width(x, r):
    depth = r.max() - r
    half = 0.5 * depth.max()
    i = int(np.argmax(depth))
    lo = i
    while lo > 0 and depth[lo] > half:
        lo -= 1
    hi = i
    while hi < len(r) - 1 and depth[hi] > half:
        hi += 1
    if depth[lo] > half or depth[hi] > half:
        return float("nan")  # the dip is wider than the probed range
    xl = np.interp(half, [depth[lo], depth[lo + 1]], [x[lo], x[lo + 1]])
    xh = np.interp(half, [depth[hi], depth[hi - 1]], [x[hi], x[hi - 1]])
    return xh - xl


def evaluate(directory):
    rows = read_statistics(os.path.join(directory, "statistics"))
    u = np.array([PULL * r["time"] for r in rows])
    F = np.array([4 * r["F2_x"] for r in rows])
    k = int(np.argmax(F))
    last = rows[-1]
    # The radius profile at T_CMP, interpolated between the steps around it.
    before = [r_ for r_ in rows if r_["time"] <= T_CMP + 1e-12]
    after = [r_ for r_ in rows if r_["time"] > T_CMP + 1e-12]
    at = before[-1]
    x, r = profile(at)
    if after:
        x1, r1 = profile(after[0])
        w = (T_CMP - at["time"]) / (after[0]["time"] - at["time"])
        x, r = (1 - w) * x + w * x1, (1 - w) * r + w * r1
        at = dict(at, time=T_CMP)
    n = len(r)
    w_ext = last["external_work"]
    return dict(u=u, F=F, peak=F[k], u_peak=u[k], t_end=last["time"], t_cmp=at["time"],
                residual=last["energy_residual"] / w_ext if w_ext else 0.,
                dissipation=last.get("plastic_dissipation", float("nan")),
                min_local=min(r_.get("min_plastic_dissipation", 0.) for r_ in rows),
                radius=r[n // 2], width=neck_width(x, r), x=x, r=r,
                newton=int(sum(r_["newton_iterations"] for r_ in rows)),
                time=wall_time(os.path.join(directory, "screen.txt")))


def main(here):
    runs, dt_runs, hold_runs = {}, {}, {}
    for name in sorted(os.listdir(os.path.join(here, "runs"))):
        d = os.path.join(here, "runs", name)
        if not os.path.exists(os.path.join(d, "statistics")):
            continue
        if "-hold" in name:
            hold_runs[name] = evaluate(d)
            continue
        if "-dt" in name:
            dt_runs[float(name.split("-dt")[1])] = evaluate(d)
            continue
        if name == "a20-r1-lp1e-3":  # the scene's mesh and time step
            dt_runs[0.02] = evaluate(d)
        mesh, lp = name[1:].split("-lp")
        axial, refine = mesh.split("-r")
        # cells along the half bar, and per quarter cross-section
        runs[(float(lp), int(axial) * 2 ** int(refine) // 2,
              5 * 4 ** (int(refine) - 1))] = evaluate(d)
    out = ["# Necking bar: peak force, neck radius and width against run time", "",
           "prm/necking_bar.prm (R0 = 6.413 mm, L = 53.334 mm, 1.8 % taper, octant model, pulled 14 mm",
           "in 50 steps of 0.28 mm, 2 MPI ranks). Mesh: Q2 cells along the half bar x cells per quarter",
           "cross-section. Neck radius and width at 11.2 mm (t = 0.8); errors against the finest run",
           "with the same l_p (marked ref). end u: where the run stopped (see README).", "",
           "| l_p [mm] | mesh | end u [mm] | peak F [kN] | u at peak [mm] | neck radius [mm] | neck width [mm] | Newton its | run time [s] | peak err | radius err | width err |",
           "|---|---|---|---|---|---|---|---|---|---|---|---|"]
    for lp in sorted({k[0] for k in runs}, reverse=True):
        meshes = sorted((m for (l, *m) in runs if l == lp), key=lambda m: m[0] * m[1])
        done = [m for m in meshes if abs(runs[(lp, *m)]["t_cmp"] - T_CMP) < 1e-9]
        ref = runs[(lp, *done[-1])] if done else None
        for m in meshes:
            a = m
            v = runs[(lp, *m)]
            err = ["", "", ""]
            if ref is not None and a != done[-1] and a in done:
                err = [f"{v['peak'] / ref['peak'] - 1:+.2%}",
                       f"{v['radius'] / ref['radius'] - 1:+.2%}",
                       f"{v['width'] / ref['width'] - 1:+.1%}"]
            elif ref is not None and a == done[-1]:
                err = ["ref", "ref", "ref"]
            t = f"{v['time']:.0f}" if v["time"] else "(unfinished)"
            out.append(f"| {lp * 1e3:g} | {m[0]} x {m[1]} | {PULL * v['t_end'] * 1e3:.2f} | {v['peak'] / 1e3:.2f} | "
                       f"{v['u_peak'] * 1e3:.2f} | {v['radius'] * 1e3:.3f} | {v['width'] * 1e3:.2f} | "
                       f"{v['newton']} | {t} | " + " | ".join(err) + " |")
    out += ["", "Energy account at the end (model's own terms): energy_residual / W_ext, plastic "
            "dissipation D_p [J] and the smallest local D_p of any step [J/m^3]:", "",
            "| l_p [mm] | mesh | residual / W_ext | D_p [J] | min local D_p [J/m^3] |",
            "|---|---|---|---|---|"]
    for (lp, *m), v in sorted(runs.items(), key=lambda kv: (-kv[0][0], kv[0][1] * kv[0][2])):
        out.append(f"| {lp * 1e3:g} | {m[0]} x {m[1]} | {v['residual']:+.3%} | "
                   f"{v['dissipation']:.4g} | {v['min_local']:.3g} |")
    if len(dt_runs) > 1:
        out += ["", "Time-step study, l_p = 1 mm, 20 x 5 cells (the scene's mesh): time step t "
                "(elongation 14 mm t), the same quantities; differences to the next finer step.", "",
                "| time step | peak F [kN] | neck radius [mm] | neck width [mm] | residual / W_ext | "
                "D_p [J] | min local D_p [J/m^3] | Newton its | run time [s] | radius change | width change |",
                "|---|---|---|---|---|---|---|---|---|---|---|"]
        steps = sorted(dt_runs)
        for i, dt in enumerate(steps):
            v = dt_runs[dt]
            change = ["", ""]
            if i > 0:
                f = dt_runs[steps[i - 1]]
                change = [f"{(v['radius'] - f['radius']) * 1e3:+.4f} mm",
                          f"{(v['width'] - f['width']) * 1e3:+.3f} mm"]
            t = f"{v['time']:.0f}" if v["time"] else "(unfinished)"
            out.append(f"| {dt:g} | {v['peak'] / 1e3:.3f} | {v['radius'] * 1e3:.4f} | "
                       f"{v['width'] * 1e3:.3f} | {v['residual']:+.3%} | {v['dissipation']:.4g} | "
                       f"{v['min_local']:.3g} | {v['newton']} | {t} | " + " | ".join(change) + " |")
    if hold_runs and 0.02 in dt_runs:
        out += ["", "The hold of alpha at non-yielding points (Plasticity/Hold stiffness factor f), "
                "20 x 5 cells, time step 0.02:", "",
                "| f | peak F [kN] | neck radius [mm] | residual / W_ext | D_p [J] | "
                "min local D_p [J/m^3] | Newton its |", "|---|---|---|---|---|---|---|"]
        for label, v in [("1", dt_runs[0.02])] + [(n.split("-hold")[1], v)
                                                  for n, v in sorted(hold_runs.items())]:
            out.append(f"| {label} | {v['peak'] / 1e3:.3f} | {v['radius'] * 1e3:.4f} | "
                       f"{v['residual']:+.3%} | {v['dissipation']:.4g} | {v['min_local']:.3g} | "
                       f"{v['newton']} |")
    open(os.path.join(here, "results.md"), "w").write("\n".join(out) + "\n")
    print("\n".join(out))

    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    fig, ax = plt.subplots(1, 2, figsize=(11, 4.2))
    for (lp, *m), v in sorted(runs.items()):
        style = "-" if lp > 0 else "--"
        label = f"l_p = {lp * 1e3:g} mm, {m[0]} x {m[1]} cells"
        ax[0].plot(v["u"] * 1e3, v["F"] / 1e3, style, label=label)
        ax[1].plot((v["x"] - 0.5 * L) * 1e3, v["r"] * 1e3, style, label=label)
    ax[0].axhline(76.88, color="gray", lw=0.8, ls=":")
    ax[0].set_xlabel("elongation [mm]")
    ax[0].set_ylabel("force 4 F2_x [kN]")
    ax[0].set_title("force (dotted: Considere, thinnest section, 76.9 kN)")
    ax[1].set_xlabel("x - L/2, deformed [mm]")
    ax[1].set_ylabel("hull radius at 11.2 mm elongation [mm]")
    ax[1].set_title("radius profile")
    ax[0].legend(fontsize=7)
    fig.tight_layout()
    fig.savefig(os.path.join(here, "necking.png"), dpi=110)


if __name__ == "__main__":
    main(sys.argv[1] if len(sys.argv) > 1 else os.path.dirname(os.path.abspath(__file__)))
