#!/usr/bin/env python3
"""results.md of run.sh: the paper's scene as an impact against dt."""
import pathlib
import re
import sys

here = pathlib.Path(sys.argv[1] if len(sys.argv) > 1 else pathlib.Path(__file__).parent)


def table(path):
    rows = [l.split() for l in open(path) if l.strip() and not l.startswith('#')]
    return {h: [float(r[i]) for r in rows[1:]] for i, h in enumerate(rows[0])}


def key(run):
    """(speed, dt, plane strain, options) from runs/v<speed>_dt<dt>[_2d][_bound]."""
    m = re.match(r"v([0-9.]+)_dt([0-9.e-]+?)(_2d)?(_bound)?$", run.name)
    return float(m.group(1)), float(m.group(2)), m.group(3) is not None, m.group(4) or ""


def revision(run):
    text = (run / "log.txt").read_text() if (run / "log.txt").exists() else ""
    m = re.search(r"revision (\S+)", text)
    return m.group(1).rstrip(",") if m else "?"


def finished(run):
    screen = run / "screen.txt"
    return (run / "statistics").exists() and screen.exists() and \
        "Total wallclock" in screen.read_text()


# The quantities compared across dt, at the end of the run.
QOIS = [("plastic_work", "W_p [J]"), ("contact1_dissipation", "D_c [J]"),
        ("kinetic_energy", "K [J]"), ("stored_energy", "Ψ^e [J]"),
        ("numerical_dissipation", "D_num [J]"), ("max_alpha", "largest α"),
        ("max_s_points", "largest s")]

def value(s, column):
    """The value compared: the largest over the run for alpha and s, else
    the one at the end."""
    return max(s[column]) if column.startswith("max_") else s[column][-1]


lines = ["# The paper's scene as an impact", "",
         "From `run.sh` (prm/block_impact.prm; in plane strain prm/block_impact_2d.prm, "
         "energies per unit thickness [J/m]); the commit each run ran is in its log.txt. "
         "K₀ the block's kinetic energy at launch; the residual is W_ext − (K − K₀) − D_num − "
         "Ψ^e − Ψ^p − D_p − g_c∫γ − D_f − D_c (W_ext = 0: nothing is prescribed but the "
         "clamp), its worst the largest magnitude over the steps. Values at the end (1 ms); the "
         "largest α and s over the run (at the quadrature points).", ""]
runs = [r for r in (here / "runs").glob("v*_dt*") if finished(r)]
for speed, two_d, options in sorted({(key(r)[0], key(r)[2], key(r)[3]) for r in runs}):
    group = sorted((r for r in runs if key(r)[0] == speed and key(r)[2] == two_d
                    and key(r)[3] == options), key=lambda r: -key(r)[1])
    data = {r: table(r / "statistics") for r in group}
    finest = data[group[-1]]
    lines += [f"## {speed:g} m/s" + (", plane strain" if two_d else "")
              + (", Loading condition = bound and Bernstein α" if options else ""), "",
              "| dt [µs] | commit | end time [ms] | K₀ [J] | residual / K₀ | worst / K₀ | "
              + " | ".join(q[1] for q in QOIS)
              + " | min D_p,loc | Newton iterations | cut-backs | wall [s] |",
              "|---" * (10 + len(QOIS)) + "|"]
    for r in group:
        s = data[r]
        k0 = s["kinetic_energy"][0]
        worst = max(abs(x) for x in s["energy_residual"])
        lines.append(
            f"| {key(r)[1] * 1e6:g} | {revision(r)} | {s['time'][-1] * 1e3:.3g} | {k0:.4g} | "
            f"{s['energy_residual'][-1] / k0:.3e} | {worst / k0:.3e} | "
            + " | ".join(f"{value(s, q):.5g}" for q, _ in QOIS)
            + f" | {min(s['min_plastic_dissipation']):.3g} | {sum(s['newton_iterations']):.0f} | "
            f"{sum(s['cutbacks']):.0f} | {s['wall_time'][-1]:.0f} |")
    lines += ["", "Differences to the finest run at the end (the same columns):", "",
              "| dt [µs] | " + " | ".join(q[1] for q in QOIS) + " |",
              "|---" * (1 + len(QOIS)) + "|"]
    for r in group[:-1]:
        s = data[r]
        lines.append(f"| {key(r)[1] * 1e6:g} | "
                     + " | ".join(f"{value(s, q) - value(finest, q):.3g}" for q, _ in QOIS)
                     + " |")
    lines.append("")
(here / "results.md").write_text("\n".join(lines) + "\n")
print("\n".join(lines))
