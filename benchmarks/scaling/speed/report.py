#!/usr/bin/env python3
"""results.md of run.sh: time per Newton iteration of steps 2 and 3 (the
set-up and the first step's factorisation or AMG set-up left out), strong
and weak efficiency on 1 and 2 ranks, with each run's force and energy
residual beside it (the same physics must give the same answer)."""
import pathlib
import re

here = pathlib.Path(__file__).parent


def table(path):
    rows = [l.split() for l in open(path) if l.strip() and not l.startswith('#')]
    return {h: [float(r[i]) for r in rows[1:]] for i, h in enumerate(rows[0])}


def unknowns(run):
    m = re.search(r"DoFs: (\d+)",
                  (run / "log.txt").read_text())
    return int(m.group(1)) if m else 0


def revision(run):
    m = re.search(r"revision (\S+)", (run / "log.txt").read_text())
    return m.group(1).rstrip(",") if m else "?"


rows = {}
for run in sorted((here / "runs").glob("*-np*")):
    if not (run / "statistics").exists():
        continue
    name, solver, np_ = re.match(r"(\w+)-(direct|gmres-amg)-np(\d)", run.name).groups()
    s = table(run / "statistics")
    # steps 2 and 3: rows 2 and 3 (row 0 is t = 0)
    its = s["newton_iterations"][2] + s["newton_iterations"][3]
    wall = s["wall_time"][3] - s["wall_time"][1]
    w_ext = s["external_work"][3]
    rows[(name, solver, int(np_))] = dict(
        n=unknowns(run), its=its, per_it=wall / its, force=s["F2_z"][3],
        residual=abs(s["energy_residual"][3]) / w_ext if w_ext else 0.,
        revision=revision(run))

lines = ["# Strong and weak scaling on 1 and 2 ranks", "",
         "From `run.sh`: the 3-D two bodies, 3 steps; time per Newton iteration of steps 2 "
         "and 3 (wall time over Newton iterations, set-up and first step left out); µs·core "
         "per unknown = time × ranks / unknowns. The commit of each run is its log.txt's.", "",
         "| case | solver | ranks | unknowns | Newton its (steps 2-3) | s per Newton it | "
         "µs·core per unknown | F2_z [N] | residual / W_ext | commit |",
         "|---|---|---|---|---|---|---|---|---|---|"]
for (name, solver, p), r in sorted(rows.items()):
    lines.append(f"| {name} | {solver} | {p} | {r['n']} | {r['its']:.0f} | {r['per_it']:.3g} | "
                 f"{r['per_it'] * p / r['n'] * 1e6:.3g} | {r['force']:.6g} | "
                 f"{r['residual']:.2e} | {r['revision']} |")
lines += ["", "| solver | strong: r1x1 on 1 → 2 ranks, speed-up (efficiency) | "
          "weak: r0x1 (1 rank) → r0x2 (2 ranks), efficiency | "
          "weak: r1x1 (1 rank) → r1x2 (2 ranks), efficiency |", "|---|---|---|---|"]
for solver in ("direct", "gmres-amg"):
    cells = []
    a, b = rows.get(("r1x1", solver, 1)), rows.get(("r1x1", solver, 2))
    cells.append(f"{a['per_it'] / b['per_it']:.2f} ({a['per_it'] / b['per_it'] / 2:.0%})"
                 if a and b else "—")
    for small, big in (("r0x1", "r0x2"), ("r1x1", "r1x2")):
        a, b = rows.get((small, solver, 1)), rows.get((big, solver, 2))
        cells.append(f"{a['per_it'] / b['per_it']:.0%}" if a and b else "—")
    lines.append(f"| {solver} | " + " | ".join(cells) + " |")
(here / "results.md").write_text("\n".join(lines) + "\n")
print("\n".join(lines))

# speed.png: time per Newton iteration against the ranks, strong (the same
# mesh) and weak (twice the unknowns on twice the ranks), with the ideal lines.
try:
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
except ImportError:
    raise SystemExit("matplotlib missing: no plot")
fig, axes = plt.subplots(1, 2, figsize=(9, 3.8))
for solver, colour in (("direct", "C0"), ("gmres-amg", "C1")):
    a, b = rows.get(("r1x1", solver, 1)), rows.get(("r1x1", solver, 2))
    if a and b:
        axes[0].plot([1, 2], [a["per_it"], b["per_it"]], "o-", color=colour, label=solver)
        axes[0].plot([1, 2], [a["per_it"], a["per_it"] / 2], ":", color=colour)
    for small, big, style in (("r0x1", "r0x2", "s--"), ("r1x1", "r1x2", "o-")):
        a, b = rows.get((small, solver, 1)), rows.get((big, solver, 2))
        if a and b:
            axes[1].plot([1, 2], [a["per_it"], b["per_it"]], style, color=colour,
                         label=f"{solver}, {round(a['n'] / 1000)}k per rank")
            axes[1].plot([1, 2], [a["per_it"], a["per_it"]], ":", color=colour)
axes[0].set_title("strong: 138k unknowns (dotted: ideal)")
axes[1].set_title("weak: unknowns per rank fixed (dotted: ideal)")
for ax in axes:
    ax.set_xticks([1, 2])
    ax.set_xlabel("ranks")
    ax.set_ylabel("s per Newton iteration")
    ax.set_yscale("log")
    ax.legend(fontsize=7)
fig.tight_layout()
fig.savefig(here / "speed.png", dpi=120)
