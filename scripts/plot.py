#!/usr/bin/python3
"""Plots statistics columns of a run against time or another column.

Usage: scripts/plot.py RESULTS [COLUMN ...] [--x COLUMN] [--abs]
                       [--out FILE.png] [--title TEXT]
  RESULTS   a results directory holding `statistics`, or the file itself
  COLUMN    columns to draw, one panel each (default: the forces on the
            prescribed boundaries, the energies with the energy-balance
            residual, and the Newton iterations per step)
  --x       the abscissa (default: time), e.g. u2_z for a force curve
  --abs     draw absolute values (a downward force against a downward
            displacement as a positive curve)
  --out     the picture (default: RESULTS/plot.png)
Column names and their units: doc/output.md; `head -1 RESULTS/statistics`
lists those of a run.
"""
import argparse
import os
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

ENERGIES = ["external_work", "stored_energy", "plastic_work",
            "hardening_energy", "fracture_energy", "fracture_viscous_work",
            "history_driving_work", "energy_residual"]


def read(path):
    lines = [l for l in open(path).read().split("\n") if l.strip()]
    names = lines[0].split()
    rows = [list(map(float, l.split())) for l in lines[1:]]
    return {n: [r[i] for r in rows] for i, n in enumerate(names)}


def unit(name):
    if name.startswith("F") and name[1:2].isdigit() or name.endswith(
            ("_force_x", "_force_y", "_force_z", "_friction_x", "_friction_y",
             "_friction_z")):
        return "N"
    if name.startswith("u") and name[1:2].isdigit() or name.endswith(
            ("penetration", "max_slip")):
        return "m"
    if name in ENERGIES or name.endswith("dissipation"):
        return "J"
    if name.endswith("pressure"):
        return "Pa"
    if name.endswith("area"):
        return "m²"
    if name.endswith("_time"):
        return "s"
    return ""


def label(name, absolute):
    u = unit(name)
    text = f"|{name}|" if absolute else name
    return f"{text} [{u}]" if u else text


def default_columns(data):
    """The force components on prescribed boundaries above round-off, the
    energies, the Newton iterations."""
    forces = [n for n in data if n[:1] == "F" and n[1:2].isdigit()]
    largest = max((abs(v) for n in forces for v in data[n]), default=0.)
    # Components at round-off of the largest force are left out.
    forces = [n for n in forces
              if any(abs(v) > 1e-6 * largest for v in data[n])]
    energies = [n for n in ENERGIES if n in data
                and any(abs(v) > 0 for v in data[n])]
    groups = [[f] for f in forces]
    if energies:
        groups.append(energies)
    if "newton_iterations" in data:
        groups.append(["newton_iterations"])
    return groups


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("results")
    parser.add_argument("columns", nargs="*")
    parser.add_argument("--x", default="time")
    parser.add_argument("--abs", action="store_true")
    parser.add_argument("--out")
    parser.add_argument("--title")
    args = parser.parse_args()
    path = args.results
    if os.path.isdir(path):
        path = os.path.join(path, "statistics")
    if not os.path.isfile(path):
        sys.exit(f"error: no statistics file {path}")
    data = read(path)
    groups = [[c] for c in args.columns] or default_columns(data)
    for name in [args.x] + [c for g in groups for c in g]:
        if name not in data:
            sys.exit(f"error: no column '{name}' in {path}; it has: "
                     + " ".join(data))
    value = (lambda v: [abs(x) for x in v]) if args.abs else (lambda v: v)
    x = value(data[args.x])
    fig, axes = plt.subplots(len(groups), 1, sharex=True, squeeze=False,
                             figsize=(7, 2.6 * len(groups) + 0.6))
    for ax, group in zip(axes[:, 0], groups):
        for name in group:
            ax.plot(x, value(data[name]), marker="." if len(x) < 60 else None,
                    label=name)
        if len(group) == 1:
            ax.set_ylabel(label(group[0], args.abs))
        else:
            ax.set_ylabel(f"[{unit(group[0])}]")
            ax.legend(fontsize=7, ncol=2)
        ax.grid(alpha=0.3)
    axes[-1, 0].set_xlabel(label(args.x, args.abs))
    fig.suptitle(args.title or os.path.basename(
        os.path.dirname(os.path.abspath(path))))
    fig.tight_layout()
    out = args.out or os.path.join(os.path.dirname(path), "plot.png")
    fig.savefig(out, dpi=120)
    print(f"-- wrote {out}")


if __name__ == "__main__":
    main()
