#!/usr/bin/python3
"""Collects a parameter study of scripts/study.sh into DIR/study.csv (one
row per run) and draws chosen columns against a swept entry.

Usage: scripts/study_report.py DIR [--force COLUMN] [--plot COLUMN:ENTRY]...
  --force  the force column (default: the F<id>_<x|y|z> column of largest
           magnitude in the first finished run)
  --plot   COLUMN of the CSV against the swept ENTRY, one line per value of
           the other swept entries; written to DIR/COLUMN-vs-ENTRY.png
Columns: the swept entries, peak_force [N] (largest |force|), final_force
[N], max_s, max_alpha [-], crack_energy [J], contact_dissipation [J] (all
pairs), newton_iterations, wall_time [s], exit_code (0 done, 1 bad input,
2 the load stepping gave up; other: killed or crashed). A run without
statistics has empty result columns.
"""
import argparse
import csv
import os
import re
import sys

COLUMNS = ["peak_force", "final_force", "max_s", "max_alpha", "crack_energy",
           "contact_dissipation", "newton_iterations", "wall_time",
           "exit_code"]


def read_statistics(path):
    lines = [l for l in open(path).read().split("\n") if l.strip()]
    names = lines[0].split()
    return [dict(zip(names, map(float, l.split()))) for l in lines[1:]]


def force_column(rows):
    forces = [n for n in rows[0] if re.fullmatch(r"F\d+_[xyz]", n)]
    return max(forces, key=lambda n: max(abs(r[n]) for r in rows),
               default=None)


def results(run, force):
    stats = os.path.join(run, "statistics")
    values = {c: "" for c in COLUMNS}
    code = os.path.join(run, "exit_code")
    values["exit_code"] = open(code).read().strip() if os.path.isfile(
        code) else "not run"
    wall = os.path.join(run, "wall_time_ms")
    if os.path.isfile(wall):
        values["wall_time"] = f"{int(open(wall).read()) / 1000:.1f}"
    if not os.path.isfile(stats):
        return values
    rows = read_statistics(stats)
    if len(rows) < 2:
        return values
    last = rows[-1]
    if force and force in last:
        values["peak_force"] = f"{max(abs(r[force]) for r in rows):.6g}"
        values["final_force"] = f"{last[force]:.6g}"
    for column, name in (("max_s", "max_s"), ("max_alpha", "max_alpha"),
                         ("crack_energy", "fracture_energy")):
        if name in last:
            values[column] = f"{last[name]:.6g}"
    dissipation = [n for n in last if re.fullmatch(r"contact\d+_dissipation",
                                                    n)]
    if dissipation:
        values["contact_dissipation"] = \
            f"{sum(last[n] for n in dissipation):.6g}"
    values["newton_iterations"] = \
        f"{sum(r['newton_iterations'] for r in rows):.0f}"
    return values


def plot(table, entries, column, entry, out):
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    others = [e for e in entries if e != entry]
    groups = {}
    for row in table:
        if row[column] == "":
            continue
        key = tuple(row[e] for e in others)
        groups.setdefault(key, []).append((float(row[entry]),
                                           float(row[column])))
    fig, ax = plt.subplots(figsize=(6, 4))
    for key, points in sorted(groups.items()):
        points.sort()
        label = ", ".join(f"{e.split('/')[-1]} = {v}"
                          for e, v in zip(others, key)) or None
        ax.plot(*zip(*points), marker="o", label=label)
    ax.set_xlabel(entry)
    ax.set_ylabel(column)
    ax.grid(alpha=0.3)
    if others:
        ax.legend(fontsize=7)
    fig.tight_layout()
    fig.savefig(out, dpi=120)
    print(f"-- wrote {out}")


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("dir")
    parser.add_argument("--force")
    parser.add_argument("--plot", action="append", default=[])
    args = parser.parse_args()
    entries = open(os.path.join(args.dir, "swept_entries")).read().split("\n")
    entries = [e for e in entries if e]
    combinations = [l.split("\t") for l in open(os.path.join(
        args.dir, "combinations")).read().split("\n") if l]
    runs = [os.path.join(args.dir, f"run_{k + 1}")
            for k in range(len(combinations))]
    force = args.force
    if not force:
        for run in runs:
            stats = os.path.join(run, "statistics")
            if os.path.isfile(stats) and len(read_statistics(stats)) > 1:
                force = force_column(read_statistics(stats))
                break
    table = []
    for run, values in zip(runs, combinations):
        row = dict(zip(entries, values))
        row["run"] = os.path.basename(run)
        row.update(results(run, force))
        table.append(row)
    path = os.path.join(args.dir, "study.csv")
    with open(path, "w", newline="") as f:
        writer = csv.DictWriter(f, fieldnames=["run"] + entries + COLUMNS)
        writer.writeheader()
        writer.writerows(table)
    print(f"-- wrote {path} (force column {force})")
    for spec in args.plot:
        column, _, entry = spec.partition(":")
        if column not in COLUMNS or entry not in entries:
            sys.exit(f"error: --plot COLUMN:ENTRY with COLUMN one of "
                     f"{', '.join(COLUMNS)} and ENTRY a swept entry; got "
                     f"'{spec}'")
        name = re.sub(r"[^A-Za-z0-9_.-]+", "_", f"{column}-vs-{entry}")
        plot(table, entries, column, entry,
             os.path.join(args.dir, name + ".png"))


if __name__ == "__main__":
    main()
