"""Ductile notched plate benchmark report: results.md, force.png and
fields.png from runs/*/.

The slab is as thick as the mesh's h (make_sent.py), so the force per unit
thickness is F2_y / h. Per run: the peak force and the top displacement
where it occurs; u_half, the displacement where the force has fallen to
half the peak after it (the crack has crossed most of the ligament); the
largest alpha and the share of the external work dissipated plastically at
the peak; the crack energy g_c int gamma at the end against g_c x ligament
(0.5 mm) x thickness; the largest |energy residual| / W_ext; steps, Newton
iterations, cut-backs and run time. Errors against the finest run with
delta = 1e-3.
"""
import glob
import os
import re
import sys

import numpy as np

here = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, os.path.join(here, "..", ".."))
sys.path.insert(0, os.path.join(here, "..", "..", "..", "scripts"))
from runs_io import read_statistics, wall_time  # noqa: E402
from vtu_slice import draw  # noqa: E402

LIGAMENT = 0.5e-3
SHIPPED = "h0.05-delta1e-3"


def parameter(prm, name):
    return float(re.search(r"set %s\s*=\s*(\S+)" % re.escape(name), prm).group(1))


def evaluate(directory):
    name = os.path.basename(directory)
    h = float(re.match(r"h([\d.]+)-", name).group(1)) * 1e-3
    delta = float(re.search(r"delta([\d.e+-]+?)(-work|-energy|-dt|$)", name).group(1))
    driver = ("plastic work" if "-work" in name else
              "elastic and plastic energy" if "-energy" in name else "elastic")
    prm = open(os.path.join(directory, "scene.prm")).read()
    dt = float(re.findall(r"set Time step\s*=\s*(\S+)", prm)[-1])
    g_c = parameter(prm, "Critical energy release rate")
    rows = read_statistics(os.path.join(directory, "statistics"))
    screen = open(os.path.join(directory, "screen.txt")).read()
    dofs = int(re.search(r"DoFs: (\d+)", screen).group(1))
    u = np.array([r["u2_y"] for r in rows])
    F = np.array([r["F2_y"] for r in rows]) / h
    k = int(np.argmax(F))
    after = np.nonzero(F[k:] < 0.5 * F[k])[0]
    u_half = u[k + after[0]] if len(after) else float("nan")
    w_ext = np.array([r["external_work"] for r in rows])
    res = np.array([r["energy_residual"] for r in rows])
    worst_res = max(abs(r) / w for r, w in zip(res[1:], w_ext[1:]))
    dissipation = [r.get("plastic_dissipation", float("nan")) for r in rows]
    return dict(name=name, h=h, delta=delta, driver=driver, dt=dt,
                d_p=dissipation[-1], w_p=rows[-1]["plastic_work"],
                min_local=min(r.get("min_plastic_dissipation", 0.) for r in rows),
                max_s=max(r["max_s"] for r in rows), dofs=dofs, u=u, F=F, peak=F[k], u_peak=u[k],
                u_half=u_half, alpha_peak=rows[k]["max_alpha"],
                wp_share=rows[k]["plastic_work"] / rows[k]["external_work"],
                crack=rows[-1]["fracture_energy"] / (g_c * LIGAMENT * h),
                worst_res=worst_res, end_u=u[-1], steps=len(rows) - 1,
                newton=int(sum(r["newton_iterations"] for r in rows)),
                cutbacks=int(sum(r["cutbacks"] for r in rows)),
                time=wall_time(os.path.join(directory, "screen.txt")))


def main():
    runs = [evaluate(d) for d in sorted(glob.glob(os.path.join(here, "runs", "*")))
            if os.path.exists(os.path.join(d, "statistics"))]
    runs.sort(key=lambda r: (r["driver"], -r["h"], r["delta"], -r["dt"]))
    with_ref = [r for r in runs
                if r["delta"] == 1e-3 and r["driver"] == "elastic" and r["dt"] == 0.01]
    ref = min(with_ref, key=lambda r: r["h"]) if with_ref else None

    lines = ["# Ductile notched plate: force, crack and plastic work against run time", "",
             "prm/ductile_notch.prm (single-edge-notched steel plate, gradient plasticity + crack phase",
             "field, plane strain slab, top pulled 30 um, 2 MPI ranks). F per unit thickness; u_half:",
             "top displacement where the force has fallen to half its peak; crack energy / g_c A with",
             "A = ligament x thickness; residual: largest |energy residual| / W_ext over the run.",
             "time step: of the load (u = 30 um t). D_p / W_p: plastic dissipation over plastic",
             "work at the end (model's own terms); min local D_p: the smallest over points and steps.",
             "Errors against the finest run with delta = 1e-3 and the scene's time step (ref).", "",
             "| crack driver | h [mm] | delta | time step | unknowns | end u [um] | peak F [kN/mm] | u at peak [um] | u_half [um] "
             "| max alpha at peak | W_p / W_ext at peak | crack energy / g_c A | max s | residual | D_p / W_p "
             "| min local D_p [J/m^3] | steps | Newton its | cut-backs | run time [s] | peak err | u_half err |",
             "|" + "---|" * 22]
    for r in runs:
        t = "%.0f" % r["time"] if r["time"] else "stopped"
        if r is ref:
            errs = "ref | ref"
        elif ref:
            errs = "%+.2f%% | %+.1f%%" % (100 * (r["peak"] / ref["peak"] - 1),
                                          100 * (r["u_half"] / ref["u_half"] - 1))
        else:
            errs = " | "
        lines.append("| %s | %.3g | %.0e | %g | %d | %.1f | %.4f | %.2f | %.2f | %.4f | %.2f | %.2f "
                     "| %.4f | %.1e | %+.2e | %.3g | %d | %d | %d | %s | %s |" % (
                         r["driver"], r["h"] * 1e3, r["delta"], r["dt"], r["dofs"], r["end_u"] * 1e6,
                         r["peak"] / 1e6, r["u_peak"] * 1e6, r["u_half"] * 1e6, r["alpha_peak"],
                         r["wp_share"], r["crack"], r["max_s"], r["worst_res"],
                         r["d_p"] / r["w_p"] if r["w_p"] else float("nan"), r["min_local"],
                         r["steps"], r["newton"], r["cutbacks"], t, errs))
    open(os.path.join(here, "results.md"), "w").write("\n".join(lines) + "\n")
    print("\n".join(lines))

    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    fig, ax = plt.subplots(figsize=(6.5, 4.5))
    for r in runs:
        ax.plot(r["u"] * 1e6, r["F"] / 1e6,
                label="h = %.3g mm, delta = %.0e, step %g%s" % (
                    r["h"] * 1e3, r["delta"], r["dt"],
                    ", " + r["driver"] + " driver" if r["driver"] != "elastic" else ""))
    ax.set_xlabel("top displacement u [um]")
    ax.set_ylabel("force per unit thickness [kN/mm]")
    ax.set_title("ductile notched plate (prm/ductile_notch.prm)", fontsize=9)
    ax.grid(alpha=0.3)
    ax.legend(fontsize=8)
    fig.tight_layout()
    fig.savefig(os.path.join(here, "force.png"), dpi=130)

    shipped = os.path.join(here, "runs", SHIPPED)
    outputs = sorted(glob.glob(os.path.join(shipped, "solution_*.pvtu")))
    if outputs:
        fig, axes = plt.subplots(1, 2, figsize=(8, 6.5))
        for ax, field, cmap in zip(axes, ("s", "alpha"), ("viridis", "magma")):
            collection = draw(ax, outputs[-1], field, warp=10.0, cmap=cmap)
            fig.colorbar(collection, ax=ax, label=field, shrink=0.7)
            ax.set_xlabel("x [m]")
        axes[0].set_ylabel("y [m]")
        step = re.search(r"solution_(\d+)", outputs[-1]).group(1)
        fig.suptitle("%s, output %s (displacement x 10): crack s and plastic strain alpha"
                     % (SHIPPED, step), fontsize=9)
        fig.tight_layout()
        fig.savefig(os.path.join(here, "fields.png"), dpi=130)


if __name__ == "__main__":
    main()
