#!/usr/bin/env python3
"""results.md of run.sh: the coarse paper scene as an impact against dt."""
import pathlib
import re
import sys

here = pathlib.Path(sys.argv[1] if len(sys.argv) > 1 else pathlib.Path(__file__).parent)


def table(path):
    rows = [l.split() for l in open(path) if l.strip() and not l.startswith('#')]
    return {h: [float(r[i]) for r in rows[1:]] for i, h in enumerate(rows[0])}


lines = ["# The paper's scene as an impact (coarse mesh)", "",
         "From `run.sh`; the commit each run ran is in its log.txt. K₀ the block's kinetic "
         "energy at launch; the residual is W_ext − (K − K₀) − D_num − Ψ^e − Ψ^p − D_p − "
         "g_c∫γ − D_f − D_c (W_ext = 0: nothing is prescribed but the clamp).", "",
         "| speed [m/s] | μ_c | ρ∞ | dt [µs] | commit | K₀ [J] | residual at the end / K₀ | worst / K₀ | "
         "plastic work [J] | largest α | largest s | friction [J] | D_num [J] | K at 2 ms [J] | "
         "Newton iterations | cut-backs | wall [s] |",
         "|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|"]
def key(run):
    """(speed, friction coefficient, rho_inf, dt) from
    runs/v<speed>[_mu<mu>][_rho<rho_inf>]_dt<dt>."""
    m = re.match(r"v([0-9.]+)(?:_mu([0-9.]+))?(?:_rho([0-9.]+))?_dt([0-9.e-]+)$", run.name)
    return (float(m.group(1)), float(m.group(2) or 0.2), float(m.group(3) or 1),
            float(m.group(4)))


for run in sorted((here / "runs").glob("v*_dt*"), key=lambda p: (key(p)[0], -key(p)[1], -key(p)[2], -key(p)[3])):
    if not (run / "statistics").exists():
        continue
    t = table(run / "statistics")
    log = (run / "log.txt").read_text() if (run / "log.txt").exists() else ""
    rev = re.search(r"revision\s+([0-9a-f]+)", log)
    k0 = t["kinetic_energy"][0]
    speed, mu, rho, dt = key(run)
    lines.append(
        f"| {speed:g} | {mu:g} | {rho:g} | {dt * 1e6:g} | {rev.group(1) if rev else '?'} | {k0:.5g} | "
        f"{t['energy_residual'][-1] / k0:.3e} | {max(abs(r) for r in t['energy_residual']) / k0:.3e} | "
        f"{t['plastic_work'][-1]:.4g} | {max(t['max_alpha']):.4g} | {max(t['max_s']):.4g} | "
        f"{t['contact1_dissipation'][-1]:.4g} | {t['numerical_dissipation'][-1]:.4g} | "
        f"{t['kinetic_energy'][-1]:.4g} | "
        f"{int(sum(t['newton_iterations']))} | {int(sum(t['cutbacks']))} | {t['wall_time'][-1]:.1f} |")
(here / "results.md").write_text("\n".join(lines) + "\n")
print("\n".join(lines))
