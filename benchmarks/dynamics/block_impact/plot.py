#!/usr/bin/env python3
"""results_V.png of run.sh: for the impact at V m/s, the contact force and the
energies over time for each dt, and the run time against the difference of
the plastic work and the friction dissipation to the finest run."""
import pathlib
import re
import sys

import matplotlib
matplotlib.use("Agg")
import matplotlib.pyplot as plt

here = pathlib.Path(sys.argv[1] if len(sys.argv) > 1 else pathlib.Path(__file__).parent)
speed = sys.argv[2] if len(sys.argv) > 2 else "120"
# "2d": the plane-strain runs (v<V>_dt<dt>_2d), force along y per unit
# thickness, results_V_2d.png.
two_d = len(sys.argv) > 3 and sys.argv[3] == "2d"
suffix = "_2d" if two_d else ""


def table(path):
    rows = [l.split() for l in open(path) if l.strip() and not l.startswith('#')]
    return {h: [float(r[i]) for r in rows[1:]] for i, h in enumerate(rows[0])}


def dt_of(run):
    return float(re.match(r"v[0-9.]+_dt([0-9.e-]+?)(_2d)?$", run.name).group(1))


runs = sorted((r for r in (here / "runs").glob(f"v{speed}_dt*")
               if (r / "statistics").exists() and r.name.endswith("_2d") == two_d
               and not r.name.endswith("_bound")),
              key=lambda r: -dt_of(r))
if not runs:
    sys.exit(f"no runs at {speed} m/s")
data = {r: table(r / "statistics") for r in runs}

fig, ax = plt.subplots(1, 3, figsize=(15, 4.2))
for r in runs:
    s = data[r]
    t = [x * 1e3 for x in s["time"]]
    label = f"dt = {dt_of(r) * 1e6:g} µs"
    force = s["contact1_force_y"] if two_d else s["contact1_force_z"]
    ax[0].plot(t, [-f / 1e3 for f in force], label=label)
    line, = ax[1].plot(t, s["kinetic_energy"], label=f"K, {label}")
    c = line.get_color()
    ax[1].plot(t, s["plastic_work"], "--", color=c)
    ax[1].plot(t, s["contact1_dissipation"], ":", color=c)
    ax[1].plot(t, s["energy_residual"], "-.", color=c)
ax[0].set(xlabel="t [ms]",
          ylabel="contact force on the strip, −F_y [kN/m]" if two_d else
          "contact force on the plate, −F_z [kN]",
          title=f"block at {speed} m/s" + (", plane strain" if two_d else ""))
ax[1].set(xlabel="t [ms]", ylabel="energy [J/m]" if two_d else "energy [J]",
          title="K (solid), W_p (dashed), D_c (dotted), residual (dash-dot)")
ax[0].legend()
ax[1].legend(fontsize=8)

finest = data[runs[-1]]
for column, name in [("plastic_work", "W_p"), ("contact1_dissipation", "D_c"),
                     ("kinetic_energy", "K at the end")]:
    xs, ys = [], []
    for r in runs[:-1]:
        wall = data[r]["wall_time"][-1]
        xs.append(abs(data[r][column][-1] - finest[column][-1]) / finest["kinetic_energy"][0])
        ys.append(wall)
    ax[2].loglog(xs, ys, "o-", label=name)
    for x, y, r in zip(xs, ys, runs[:-1]):
        ax[2].annotate(f"{dt_of(r) * 1e6:g} µs", (x, y), fontsize=8)
ax[2].set(xlabel=f"|difference to dt = {dt_of(runs[-1]) * 1e6:g} µs| / K₀",
          ylabel="run time on 2 ranks [s]", title="cost against error in dt")
ax[2].legend()
fig.tight_layout()
fig.savefig(here / f"results_{speed}{suffix}.png", dpi=110)
print("wrote", here / f"results_{speed}{suffix}.png")
