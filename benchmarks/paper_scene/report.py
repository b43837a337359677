#!/usr/bin/python3
"""Results of the paper's scene and its variants (run.sh): per run the
unknowns, steps, Newton iterations, wall time and the split of the time
(bulk assembly, contact, linear solve); the force on the block's top face
at 16.95 mm and its peak; max s, max alpha, crack energy, plastic work,
frictional dissipation, the energy balance; and the change of the force
curve against the paper run (the convergence in eta_p, eta_f, dt and h).
Writes results.md and force.png, damage.png, energies.png."""
import math
import os
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

here = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, os.path.join(here, ".."))
from runs_io import find, read_statistics, timer_section, wall_time  # noqa: E402,E501

names = {
    "paper": "the paper's model (elastic crack driver), eta_p = 1e6, "
             "eta_f = 1e5, 0.15 mm per step",
    "eta_p_half": "eta_p halved (5e5)",
    "eta_f_half": "eta_f halved (5e4)",
    "dt_half": "load step halved (0.075 mm)",
    "clamp_refined": "plate refined once at the clamp (x > 0.22 m)",
    "block_refined": "block refined once (10 x 10 x 10 cells)",
    "clamp_adaptive": "adaptive refinement where alpha > 0.002, at most once "
                      "(unknowns: at the end)",
    "clamp_adaptive_early": "adaptive refinement where alpha > 1e-4 (from the "
                            "first yield), at most once (unknowns: at the end)",
    "clamp_adaptive2": "adaptive refinement where alpha > 0.002, at most "
                       "twice (unknowns: at the end)",
    "paper_du0.6": "the paper mesh at 0.6 mm per step, single-precision "
                   "factors (the mesh study's coarsest mesh)",
    "clamp_refined_du0.6": "clamp_refined at 0.6 mm per step, "
                           "single-precision factors",
    "hinge_refined2_du0.6": "clamp_refined and the plate refined once more "
                            "for x > 0.268 m (the hinge), 0.6 mm per step, "
                            "single-precision factors",
    "ductile_zeta1": "plastic work driver, w_c = 0, zeta = 1",
    "ductile": "plastic work driver, w_c = 5e5 J/m^3, zeta = 10",
    "ductile_zeta30": "plastic work driver, w_c = 5e5 J/m^3, zeta = 30",
}
order = list(names)


def load(variant):
    run = os.path.join(here, "runs", variant)
    stats = os.path.join(run, "statistics")
    if not os.path.isfile(stats):
        return None
    rows = read_statistics(stats)
    if len(rows) < 2:
        return None
    screen_path = os.path.join(run, "screen.txt")
    screen = open(screen_path).read() if os.path.isfile(screen_path) else ""
    return dict(rows=rows, screen=screen, wall=wall_time(screen_path)
                if screen else None,
                stopped=os.path.isfile(os.path.join(run, "NOTE")),
                ranks=find(r"on (\d+) MPI rank", screen, "?"),
                unknowns=find(r"DoFs: (\d+)", screen, "-"))


def force_at_integer_steps(rows):
    """|F2_z| at u = 0.15 mm k, k = 0..113 (every step of a halved run
    that falls on a step of the paper run)."""
    return {round(-r["u2_z"] / 0.15e-3): abs(r["F2_z"]) for r in rows
            if abs(-r["u2_z"] / 0.15e-3 - round(-r["u2_z"] / 0.15e-3)) < 1e-6}


def curve_change(rows, reference):
    """max_k |F(k) - F_ref(k)| / max F_ref over the common steps."""
    f, g = force_at_integer_steps(rows), force_at_integer_steps(reference)
    common = [k for k in f if k in g and k > 0]
    if not common:
        return None
    return max(abs(f[k] - g[k]) for k in common) / max(g.values()), \
        max(common)


def summary(variant, run, reference):
    rows = run["rows"]
    last = rows[-1]
    iterations = sum(r["newton_iterations"] for r in rows)
    screen = run["screen"]
    assembly = timer_section(screen, "assembly") + timer_section(
        screen, "assembly (line search)") + timer_section(screen, "commit history")
    contact = timer_section(screen, "contact: integration, residual") + timer_section(
        screen, "contact: integration, tangent")
    solve = timer_section(screen, "linear solve")
    balance = max(abs(r["energy_residual"] + r["history_driving_work"])
                  for r in rows[1:]) / last["external_work"]
    change = curve_change(rows, reference["rows"]) if reference else None
    wall = run["wall"]
    return [
        variant,
        f"{last['dofs']:.0f}" if "dofs" in last else run["unknowns"],
        f"{len(rows) - 1}",
        f"{last['u2_z'] * -1e3:.2f}",
        f"{iterations:.0f}",
        f"{wall:.0f} s on {run['ranks']}" if wall else
        f"{last['wall_time']:.0f} s on {run['ranks']}, "
        + ("stopped by hand" if run["stopped"] else "running"),
        f"{assembly:.0f} / {contact:.0f} / {solve:.0f}",
        f"{abs(last['F2_z']) / 1e3:.3f}",
        f"{max(abs(r['F2_z']) for r in rows) / 1e3:.3f}",
        f"{last['max_s']:.3f}", f"{last['max_alpha']:.4f}",
        f"{last['fracture_energy']:.2f}", f"{last['plastic_work']:.1f}",
        f"{last['contact1_dissipation']:.3f}",
        f"{balance:.1e}",
        f"{change[0]:.2e} (to {change[1] * 0.15:.2f} mm)"
        if change and variant != "paper" else "-",
    ]


def mesh_study(runs):
    """The three meshes at 0.6 mm per step: |F2_z| at common loads, the
    differences between successive meshes and the observed order
    log2(d1 / d2) where both differences are large enough to mean it."""
    study = ["paper_du0.6", "clamp_refined_du0.6", "hinge_refined2_du0.6"]
    if not all(v in runs for v in study):
        return []
    forces = [force_at_integer_steps(runs[v]["rows"]) for v in study]
    common = sorted(set(forces[0]) & set(forces[1]) & set(forces[2]))
    lines = ["", "## Mesh study at 0.6 mm per step", "",
             "|F2_z| [kN] on the paper mesh (h), refined once at the clamp "
             "(h/2 for x > 0.22 m) and once more at the hinge (h/4 for x > "
             "0.268 m); d1, d2: the differences h - h/2 and h/2 - h/4; order "
             "log2(d1/d2).", "",
             "| u [mm] | h | h/2 | h/4 | d1 | d2 | order |", "|---|---|---|---|---|---|---|"]
    for k in common:
        if k == 0 or (k % 16 and k != common[-1]):
            continue
        f = [g[k] / 1e3 for g in forces]
        d1, d2 = f[0] - f[1], f[1] - f[2]
        order = (f"{math.log2(d1 / d2):.2f}" if d1 * d2 > 0
                 and abs(d1) > 1e-3 * f[0] else "-")
        lines.append(f"| {k * 0.15:.2f} | {f[0]:.4f} | {f[1]:.4f} | "
                     f"{f[2]:.4f} | {d1:+.4f} | {d2:+.4f} | {order} |")
    return lines


def main():
    runs = {v: load(v) for v in order}
    runs = {v: r for v, r in runs.items() if r}
    reference = runs.get("paper")
    header = ["run", "unknowns", "steps", "u [mm]", "Newton its", "wall",
              "assembly / contact / solve [s]", "|F2_z| end [kN]",
              "peak [kN]", "max s", "max alpha", "crack energy [J]",
              "plastic work [J]", "friction [J]", "energy balance",
              "force curve change vs paper"]
    lines = ["# The paper's scene: results (generated by report.py)", "",
             "| " + " | ".join(header) + " |",
             "|" + "---|" * len(header)]
    for v, run in runs.items():
        lines.append("| " + " | ".join(summary(v, run, reference)) + " |")
    lines += ["", "Runs:"] + [f"- `{v}`: {names[v]}" for v in runs]
    lines += ["", "energy balance: the largest |W_ext - Psi^e - W_p - crack "
              "energy - viscous work - history driving work - friction| "
              "over the steps, over W_ext at the end; force curve change: "
              "the largest "
              "difference of |F2_z| at the paper run's load steps over the "
              "paper run's peak."]
    lines += mesh_study(runs)
    open(os.path.join(here, "results.md"), "w").write("\n".join(lines) + "\n")
    print("\n".join(lines))

    fig, ax = plt.subplots(figsize=(7, 4.5))
    for v, run in runs.items():
        rows = run["rows"]
        ax.plot([-r["u2_z"] * 1e3 for r in rows],
                [abs(r["F2_z"]) / 1e3 for r in rows], label=v)
    ax.set_xlabel("displacement of the block's top face [mm]")
    ax.set_ylabel("force on the block's top face |F2_z| [kN]")
    ax.grid(alpha=0.3)
    ax.legend(fontsize=8)
    fig.tight_layout()
    fig.savefig(os.path.join(here, "force.png"), dpi=120)

    fig, axes = plt.subplots(1, 2, figsize=(10, 4))
    for v, run in runs.items():
        rows = run["rows"]
        u = [-r["u2_z"] * 1e3 for r in rows]
        axes[0].plot(u, [r["max_s"] for r in rows], label=v)
        axes[1].plot(u, [r["fracture_energy"] for r in rows], label=v)
    axes[0].set_ylabel("max s")
    axes[1].set_ylabel("crack energy g_c int gamma [J]")
    for ax in axes:
        ax.set_xlabel("displacement [mm]")
        ax.grid(alpha=0.3)
    axes[0].legend(fontsize=8)
    fig.tight_layout()
    fig.savefig(os.path.join(here, "damage.png"), dpi=120)

    fig, axes = plt.subplots(1, len([v for v in ("paper", "ductile")
                                     if v in runs]) or 1, figsize=(10, 4),
                             squeeze=False)
    for ax, v in zip(axes[0], [v for v in ("paper", "ductile") if v in runs]):
        rows = runs[v]["rows"]
        u = [-r["u2_z"] * 1e3 for r in rows]
        for column in ("external_work", "stored_energy", "plastic_work",
                       "fracture_energy", "contact1_dissipation",
                       "history_driving_work", "energy_residual"):
            ax.plot(u, [r[column] for r in rows], label=column)
        ax.set_title(v)
        ax.set_xlabel("displacement [mm]")
        ax.set_ylabel("[J]")
        ax.grid(alpha=0.3)
        ax.legend(fontsize=7)
    fig.tight_layout()
    fig.savefig(os.path.join(here, "energies.png"), dpi=120)


if __name__ == "__main__":
    main()
