#!/usr/bin/env python3
"""Usage: compare_statistics.py REFERENCE RESUMED

Passes (exit 0) when the two statistics files have the same columns and
steps and agree in every column but the timings (assembly_time,
solve_time, wall_time) and the solver's work (Newton and linear
iterations, the observed Newton rate, cut-backs: the iterations depend on
the partition through round-off and the preconditioner; the smallest local
plastic dissipation, a minimum over the points of values that are zero to
round-off while nothing flows: -8.8e-6 against -1.2e-5 J/m^3 in two runs of
the plane-strain paper scene's third step) to 1e-6 of the
column's scale: for forces the largest force of the table, for lengths the
largest displacement or length, for energies the largest energy, for
contact pressures the largest pressure, for alpha columns the largest
alpha, for momentum components the largest momentum component, otherwise
the column's own largest value. (A quantity that is
round-off itself, such as a lateral force of 1e-4 N in a scene loaded with
8 kN, is then compared at the scale it is round-off of.)

Contact pressures (the largest and smallest nodal multiplier) are compared
to 1e-5 of the largest pressure: two identical runs of the coarse paper
scene on 2 ranks differ by up to 2.5e-7 in them (MUMPS's parallel
factorisation is not bit-reproducible; 1-rank runs are), runs on 1 and 2
ranks by 1e-7 to 1e-6, so 1e-6 left no margin (a resume 2 -> 1 failed at
1.0e-6 while the forces agreed to 1e-8)."""
import sys

NOT_COMPARED = {"assembly_time", "solve_time", "wall_time", "newton_iterations",
                "linear_iterations", "newton_rate", "tangent_error",
                "staggered_iterations", "contact_augmentations", "cutbacks",
                "min_plastic_dissipation"}


def read(name):
    rows = [line.split() for line in open(name) if line.strip()]
    return rows[0], [[float(v) for v in row] for row in rows[1:]]


TOLERANCE = {"pressure": 1e-5}
DEFAULT_TOLERANCE = 1e-6


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
    if column.startswith("momentum"):
        return "momentum"
    return column


def largest_difference(reference, other):
    """(largest difference in units of its column's tolerance, that
    difference in units of the column's scale, where), or raises ValueError
    when the columns or the steps differ. The files agree when the first is
    at most 1."""
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
    worst, error, where = 0., 0., ""
    for k, column in enumerate(head):
        if column in NOT_COMPARED:
            continue
        s = scale[family(column)] or 1.
        allowed = TOLERANCE.get(family(column), DEFAULT_TOLERANCE)
        for a, b in zip(ref, new):
            e = abs(a[k] - b[k]) / s
            if e / allowed > worst:
                worst, error, where = e / allowed, e, f"{column} at step {int(a[0])}"
    return worst, error, where


def main():
    try:
        worst, error, where = largest_difference(sys.argv[1], sys.argv[2])
    except ValueError as e:
        sys.exit(f"FAIL: {e}")
    rows = sum(1 for line in open(sys.argv[1]) if line.strip()) - 1
    print(f"{rows} rows, largest difference {error:.1e} of its scale"
          + (f" ({where}, {worst:.2f} of its tolerance)" if where else ""))
    if worst > 1:
        sys.exit("FAIL: the runs differ")


if __name__ == "__main__":
    main()
