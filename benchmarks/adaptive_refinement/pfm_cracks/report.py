#!/usr/bin/env python3
"""pfm-cracks' adaptive Miehe tension (runs/g4, g5, g6) next to our
adaptive notched tension (../sent/runs): peak load, unknowns, Newton
iterations and wall time to the peak; writes results.md."""
import os
import re
import sys

here = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, os.path.join(here, "..", ".."))
from runs_io import read_statistics  # noqa: E402


def pfm_curve(name, axis="y"):
    """(u [mm], load [N/mm]) per converged step of a pfm-cracks screen log
    (its 'Load y' of the tension test, 'Load x' of the shear test)."""
    path = os.path.join(here, "runs", name, "screen.log")
    if not os.path.isfile(path):
        return [], []
    u, load = [], []
    for line in open(path):
        m = re.match(r"No (\d+) time ([0-9.e+-]+) .*Load " + axis +
                     r": ([0-9.e+-]+)", line)
        if m:
            u.append(float(m.group(2)))
            load.append(float(m.group(3)))
    return u, load


def pfm_energy_peak(name):
    """The largest dW/du of a pfm-cracks run, W = its bulk plus crack
    energy per step (the reaction that its energies imply): (u at the
    middle of the step [mm], dW/du [N/mm])."""
    us, fs = pfm_energy_curve(name)
    if not fs:
        return None
    n = max(range(len(fs)), key=lambda m: fs[m])
    return us[n], fs[n]


def pfm_energy_curve(name):
    """(u [mm], dW/du [N/mm]) per step of a pfm-cracks run, at the middle
    of each step."""
    path = os.path.join(here, "runs", name, "screen.log")
    us, fs, u_old, w_old = [], [], 0.0, 0.0
    if not os.path.isfile(path):
        return us, fs
    for line in open(path):
        m = re.match(r"No \d+ time ([0-9.e+-]+) bulk energy: ([0-9.e+-]+) "
                     r"crack energy: ([0-9.e+-]+)", line)
        if not m:
            continue
        u, w = float(m.group(1)), float(m.group(2)) + float(m.group(3))
        if u > u_old:
            us.append(0.5 * (u + u_old))
            fs.append((w - w_old) / (u - u_old))
        u_old, w_old = u, w
    return us, fs


def pfm_run(name, axis="y"):
    """Peak and the cost up to it from a pfm-cracks screen log."""
    path = os.path.join(here, "runs", name, "screen.log")
    if not os.path.isfile(path):
        return None
    steps, dofs, newton, wall, solves = [], 0, 0, 0.0, 0
    pending = None
    for line in open(path):
        m = re.match(r"Timestep (\d+): .*DoFs: (\d+)", line)
        if m:
            dofs = int(m.group(2))
            solves += 1
        m = re.search(r"Newton iterations: (\d+)", line)
        if m:
            newton += int(m.group(1))
        m = re.match(r"No (\d+) time ([0-9.e+-]+) .*Load " + axis +
                     r": ([0-9.e+-]+)", line)
        if m:
            pending = dict(step=int(m.group(1)), u=float(m.group(2)),
                           load=float(m.group(3)), dofs=dofs, newton=newton,
                           solves=solves)
        m = re.search(r"Time step loop, CPU/wall time: [0-9.]+s / ([0-9.]+)s",
                      line)
        if m and pending:
            wall += float(m.group(1))
            pending["wall"] = wall
            steps.append(pending)
            pending = None
    if not steps:
        return None
    peak = max(steps, key=lambda s: s["load"])
    first = re.search(r"DoFs: \d+ solid \+ \d+ phase = (\d+)",
                      open(path).read())
    total = re.search(r"Total wallclock time elapsed since start\s*\|\s*"
                      r"([0-9.]+)s", open(path).read())
    return dict(peak=peak, start_dofs=int(first.group(1)) if first else 0,
                total=float(total.group(1)) if total else None,
                refinements=peak["solves"] - (peak["step"] + 1))


def our_run(name):
    """Peak of the force and the cost up to it from our statistics."""
    path = os.path.join(here, "runs", name, "statistics")
    if not os.path.isfile(path):
        path = os.path.join(here, "..", "sent", "runs", name, "statistics")
    if not os.path.isfile(path):
        return None
    rows = read_statistics(path)
    k = max(range(len(rows)), key=lambda n: rows[n]["F2_y"])
    # Force per thickness of the slab (run.sh of ../sent: 0.00375 mm), N/mm.
    return dict(load=rows[k]["F2_y"] / 0.00375, u=rows[k]["u2_y"] * 1e3,
                dofs=rows[k]["dofs"], start_dofs=rows[0].get("dofs", 0),
                newton=sum(r["newton_iterations"] for r in rows[1:k + 1]),
                refinements=sum(r["refinements"] for r in rows[1:k + 1]),
                wall=rows[k]["wall_time"])


def same_model_run(level, kind="at2"):
    """Our run of prm/sent_pfm_2d.prm on pfm-cracks' level-L mesh
    (same_model.sh; kind at2, or at4 for the fourth-order phase field, or
    shear for prm/sent_shear_pfm_2d.prm): the peak, the cost up to it, the
    force curve."""
    path = os.path.join(here, "runs", f"ours-{kind}-g{level}", "statistics")
    if not os.path.isfile(path):
        return None
    rows = read_statistics(path)
    axis, steps = ("x", 200.) if kind.startswith("shear") else ("y", 89.)
    # Plane strain: F2 per unit thickness [N/m] -> N/mm.
    load = [r["F2_" + axis] * 1e-3 for r in rows]
    u = [r["u2_" + axis] * 1e3 for r in rows]
    k = max(range(len(rows)), key=lambda n: load[n])
    screen = open(os.path.join(os.path.dirname(path), "screen.txt")).read()
    dofs = re.search(r"DoFs: (\d+)", screen)
    end = "Total wallclock" in screen and "exit code" not in screen.lower()
    return dict(load=load[k], u=u[k], dofs=int(dofs.group(1)) if dofs else 0,
                u_end=u[-1], reached_end=abs(rows[-1]["time"] - steps) < 1e-9,
                residual=max(abs(r["energy_residual"]) / r["external_work"]
                             for r in rows[1:]),
                newton=sum(r["newton_iterations"] for r in rows[1:k + 1]),
                wall=rows[k]["wall_time"], total=rows[-1]["wall_time"],
                curve=(u, load))


def plot_force_curves(curves, axis, fourth, ranges, titles, file_name):
    """Ours and pfm-cracks' force curves per level (its printed Load AXIS
    dashed, the dW/du of its energies dotted), our fourth-order curves
    (level, curve) dash-dotted, on two panels of the given (x0, x1, y0, y1)
    ranges and titles, saved as FILE_NAME."""
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    fig, axes = plt.subplots(1, 2, figsize=(11, 4.5))
    for ax, (x0, x1, y0, y1) in zip(axes, ranges):
        for level, (pu, pl), (ou, ol), (eu, el) in curves:
            line, = ax.plot(ou, ol, label=f"ours, level {level}")
            if pu:
                ax.plot(pu, pl, "--", color=line.get_color(),
                        label=f"pfm-cracks Load {axis}, level {level}")
                ax.plot(eu, el, ":", color=line.get_color(),
                        label=f"pfm-cracks dW/du, level {level}")
        for level, curve in fourth:
            ax.plot(*curve, "-.", label=f"ours fourth order, level {level}")
        ax.set_xlim(x0, x1)
        ax.set_ylim(y0, y1)
        ax.set_xlabel("top displacement u [mm]")
        ax.set_ylabel("load [N/mm]")
        ax.grid(alpha=0.3)
    axes[0].set_title(titles[0])
    axes[1].set_title(titles[1])
    axes[1].legend(fontsize=7)
    fig.tight_layout()
    fig.savefig(os.path.join(here, file_name), dpi=120)


def same_model_table():
    """Lines of the same-model comparison and its plot."""
    lines = ["", "## The same model (same_model.sh)", "",
             "pfm-cracks' runs g4, g5, g6 against ours with prm/sent_pfm_2d.prm "
             "(2-D, AT2 with l_f = eps = 0.0441942 mm, no split, Q1, the same "
             "89 load steps) on its uniform meshes of the same levels; "
             "pfm-cracks linear elastic with the phase field extrapolated in "
             "the displacement equation, ours neo-Hooke, monolithic. "
             "One rank each.", "",
             "| level (h) | unknowns | pfm-cracks Load y peak | at u | "
             "pfm-cracks dW/du peak | at u | ours peak | at u | ours / "
             "pfm-cracks dW/du - 1 | pfm-cracks Newton its / wall to the peak | "
             "ours Newton its / wall to the peak | ours: run ends at u |",
             "|---|---|---|---|---|---|---|---|---|---|---|---|"]
    curves = []
    for level in (4, 5, 6):
        p, o = pfm_run(f"g{level}"), same_model_run(level)
        if not o:
            continue
        h = 0.5 / 2**level
        e = pfm_energy_peak(f"g{level}")
        if p and e:
            pk = p["peak"]
            pfm = (f"{pk['load']:.1f} N/mm | {pk['u']:.5f} mm | "
                   f"{e[1]:.1f} N/mm | {e[0]:.5f} mm",
                   f"{o['load'] / e[1] - 1:+.2%}",
                   f"{pk['newton']} / {pk['wall']:.0f} s")
        else:
            pfm = ("- | - | - | -", "-", "-")
        end = ("89 steps" if o["reached_end"] else
               f"{o['u_end']:.5f} mm (gave up)")
        lines.append(f"| {level} ({h:.5g} mm) | {o['dofs']} | {pfm[0]} | "
                     f"{o['load']:.1f} N/mm | {o['u']:.5f} mm | {pfm[1]} | "
                     f"{pfm[2]} | {o['newton']:.0f} / {o['wall']:.0f} s | "
                     f"{end} |")
        curves.append((level, pfm_curve(f"g{level}"), o["curve"],
                       pfm_energy_curve(f"g{level}")))
    fourth = [(level, same_model_run(level, "at4"), same_model_run(level))
              for level in (4, 5)]
    fourth = [f for f in fourth if f[1]]
    if fourth:
        lines += ["", "The same scene with our fourth-order phase field beside it "
                  "(l_f = eps/2 = 0.0220971 mm, the same transition zone, Q2, "
                  "the same meshes):", "",
                  "| level | unknowns | fourth-order peak | at u | against "
                  "AT2 on the level | Newton its / wall to the peak | run ends at u |",
                  "|---|---|---|---|---|---|---|"]
        for level, o, a in fourth:
            versus = f"{o['load'] / a['load'] - 1:+.1%}" if a else "-"
            end = ("89 steps" if o["reached_end"] else
                   f"{o['u_end']:.5f} mm (gave up)")
            lines.append(f"| {level} | {o['dofs']} | {o['load']:.1f} N/mm | "
                         f"{o['u']:.5f} mm | {versus} | {o['newton']:.0f} / "
                         f"{o['wall']:.0f} s | {end} |")
    if curves:
        plot_force_curves(
            curves, "y",
            [(level, o["curve"]) for level, o, _ in fourth],
            [(0, 0.0063, 0, 850), (0.0052, 0.0062, 540, 820)],
            ("Notched tension, AT2, no split, Q1 (same model)",
             "near the peak (after it the crack runs unstably)"),
            "same_model.png")
        lines += ["", "![force curves](same_model.png)"]
    return lines


def shear_table():
    """Lines of the notched-shear comparison and its plot."""
    lines = ["", "## Notched shear, the same model (run.sh s4 s5 s6, "
             "same_model.sh shear-g4 ... g6)", "",
             "pfm-cracks' parameters_miehe_shear_adaptive.prm (s4 as shipped: "
             "level 4 and one adaptive level; s5, s6 uniform, eps = 0.0441942 "
             "mm) against ours with prm/sent_shear_pfm_2d.prm (2-D, AT2 with "
             "l_f = eps, small-strain linear elasticity, the spectral split, "
             "Q1, the same 200 load steps) on uniform meshes of the same "
             "levels; pfm-cracks with the phase field extrapolated in the "
             "displacement equation, ours monolithic. One rank each.", "",
             "| level (h) | unknowns | pfm-cracks Load x peak | at u | "
             "pfm-cracks dW/du peak | at u | ours peak | at u | ours / "
             "pfm-cracks dW/du - 1 | pfm-cracks Newton its / wall to the peak | "
             "ours Newton its / wall to the peak | ours: run ends at u | ours: "
             "largest energy residual / W_ext |",
             "|---|---|---|---|---|---|---|---|---|---|---|---|---|"]
    curves = []
    for level in (4, 5, 6):
        name = f"s{level}"
        p, o = pfm_run(name, "x"), same_model_run(level, "shear")
        if not o:
            continue
        h = 0.5 / 2**level
        e = pfm_energy_peak(name)
        if p and e:
            pk = p["peak"]
            pfm = (f"{pk['load']:.1f} N/mm | {pk['u']:.5f} mm | "
                   f"{e[1]:.1f} N/mm | {e[0]:.5f} mm",
                   f"{o['load'] / e[1] - 1:+.2%}",
                   f"{pk['newton']} / {pk['wall']:.0f} s")
        else:
            pfm = ("- | - | - | -", "-", "-")
        end = ("200 steps" if o["reached_end"] else
               f"{o['u_end']:.5f} mm (gave up)")
        lines.append(f"| {level} ({h:.5g} mm) | {o['dofs']} | {pfm[0]} | "
                     f"{o['load']:.1f} N/mm | {o['u']:.5f} mm | {pfm[1]} | "
                     f"{pfm[2]} | {o['newton']:.0f} / {o['wall']:.0f} s | "
                     f"{end} | {o['residual']:.1e} |")
        curves.append((level, pfm_curve(name, "x"), o["curve"],
                       pfm_energy_curve(name)))
    fourth = same_model_run(4, "shear4")
    if fourth:
        second = same_model_run(4, "shear")
        versus = f"{fourth['load'] / second['load'] - 1:+.1%}" if second else "-"
        end = ("200 steps" if fourth["reached_end"] else
               f"{fourth['u_end']:.5f} mm (gave up)")
        lines += ["", "Our fourth-order phase field beside it (l_f = eps/2, Q2, "
                  "the level-4 mesh): peak "
                  f"{fourth['load']:.1f} N/mm at {fourth['u']:.5f} mm ({versus} "
                  f"against AT2 on the level), {fourth['newton']:.0f} Newton "
                  f"its / {fourth['wall']:.0f} s to it, run ends at {end}, "
                  f"largest energy residual {fourth['residual']:.1e} of W_ext."]
    if curves:
        plot_force_curves(
            curves, "x", [(4, fourth["curve"])] if fourth else [],
            [(0, 0.02, 0, 800), (0.008, 0.0135, 300, 700)],
            ("Notched shear, AT2, spectral split, Q1 (same model)",
             "near the peak"),
            "same_model_shear.png")
        lines += ["", "![force curves](same_model_shear.png)"]
    return lines


def main():
    lines = ["# pfm-cracks and ductile-contact: adaptive notched tension "
             "(generated by report.py)", "",
             "| code, run | model | start / peak unknowns | peak load | "
             "at u | refinements to the peak | Newton its to the peak | "
             "wall to the peak | wall in all |",
             "|---|---|---|---|---|---|---|---|---|"]
    model = "2-D, second-order PF (AT2), eps = 0.0442 mm, linear elastic, no split"
    for name, what in [("g4", "level 4 + 2 adaptive (as shipped)"),
                       ("g5", "level 5 + 1 adaptive"),
                       ("g6", "level 6 uniform")]:
        r = pfm_run(name)
        if not r:
            continue
        p = r["peak"]
        total = f"{r['total']:.0f} s" if r["total"] else "stopped after the peak"
        lines.append(
            f"| pfm-cracks {name}: {what} | {model} | {r['start_dofs']} / "
            f"{p['dofs']} | {p['load']:.1f} N/mm | {p['u']:.5f} mm | "
            f"{r['refinements']} | {p['newton']} | {p['wall']:.0f} s | "
            f"{total} |")
    ours = "3-D slab (one coarse layer), 4th-order PF, l_f = 0.0075 mm, vol./dev. split, neo-Hooke"
    for name, what in [("level4-s0.2", "level 4 where s > 0.2 (../sent)"),
                       ("ours-level4-s0.2", "level 4 where s > 0.2, "
                                            "rerun beside pfm-cracks")]:
        r = our_run(name)
        if not r:
            continue
        lines.append(
            f"| ductile-contact {what} | {ours} | {r['start_dofs']:.0f} / "
            f"{r['dofs']:.0f} | {r['load']:.1f} N/mm | "
            f"{r['u']:.5f} mm | {r['refinements']:.0f} | {r['newton']:.0f} | "
            f"{r['wall']:.0f} s | - |")
    lines += same_model_table()
    lines += shear_table()
    out = "\n".join(lines) + "\n"
    open(os.path.join(here, "results.md"), "w").write(out)
    print(out)


if __name__ == "__main__":
    main()
