#!/usr/bin/env python3
"""Usage: compare_statistics.py REFERENCE RESUMED

Passes (exit 0) when the two statistics files have the same columns and
steps and agree in every column but the timings (assembly_time,
solve_time, wall_time) and the solver's work (Newton and linear
iterations, the observed Newton rate, cut-backs: the iterations depend on
the partition through round-off and the preconditioner) to 1e-6 of the column's scale: for forces the
largest force of the table, for lengths the largest displacement or
length, for energies the largest energy, for contact pressures the
largest pressure, for alpha columns the largest alpha, otherwise the column's own
largest value. (A quantity that is round-off itself, such as a lateral
force of 1e-4 N in a scene loaded with 8 kN, is then compared at the
scale it is round-off of.)"""
import sys

NOT_COMPARED = {"assembly_time", "solve_time", "wall_time", "newton_iterations",
                "linear_iterations", "newton_rate", "tangent_error",
                "staggered_iterations", "contact_augmentations", "cutbacks"}


def read(name):
    rows = [line.split() for line in open(name) if line.strip()]
    return rows[0], [[float(v) for v in row] for row in rows[1:]]


def family(column):
    if column.startswith("F") or "force" in column or "friction" in column:
        return "force"
    if (column.startswith("u") or "_u_" in column or "penetration" in column
            or "slip" in column or "gap" in column):
        return "length"
    if ("energy" in column or "work" in column or "dissipation" in column):
        return "energy"
    if "pressure" in column:
        return "pressure"
    if "alpha" in column:
        return "alpha"
    return column


def largest_difference(reference, other):
    """(largest difference in units of its column's scale, where), or
    raises ValueError when the columns or the steps differ."""
    head, ref = read(reference)
    head2, new = read(other)
    if head != head2:
        raise ValueError(f"the columns differ:\n{head}\n{head2}")
    if [r[0] for r in ref] != [r[0] for r in new]:
        raise ValueError(f"the steps differ: {[r[0] for r in ref]} vs "
                         f"{[r[0] for r in new]}")
    scale = {}
    for k, column in enumerate(head):
        top = max(abs(r[k]) for r in ref)
        scale[family(column)] = max(scale.get(family(column), 0.), top)
    worst, where = 0., ""
    for k, column in enumerate(head):
        if column in NOT_COMPARED:
            continue
        s = scale[family(column)] or 1.
        for a, b in zip(ref, new):
            error = abs(a[k] - b[k]) / s
            if error > worst:
                worst, where = error, f"{column} at step {int(a[0])}"
    return worst, where


def main():
    try:
        worst, where = largest_difference(sys.argv[1], sys.argv[2])
    except ValueError as e:
        sys.exit(f"FAIL: {e}")
    rows = sum(1 for line in open(sys.argv[1]) if line.strip()) - 1
    print(f"{rows} rows, largest difference {worst:.1e} of its scale"
          + (f" ({where})" if where else ""))
    if worst > 1e-6:
        sys.exit("FAIL: the runs differ")


if __name__ == "__main__":
    main()
