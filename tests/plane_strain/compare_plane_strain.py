#!/usr/bin/env python3
"""Usage: compare_plane_strain.py SLAB PLANE THICKNESS [QOI ...]

SLAB and PLANE are the statistics files of the same scene run as a 3-D slab
of THICKNESS with u_z = 0 on both faces and in plane strain (Dimension = 2).
The plane-strain discrete problem is the slab's restricted to fields that do
not depend on z, and the slab's solution is such a field (the problem is
symmetric in z), so the two runs must agree to the solvers' tolerance (for
a plane-stress PLANE, a SLAB whose stress state is uniaxial in the plane):
every column of PLANE that SLAB has too, the slab's forces, energies and
works, momenta and areas divided by THICKNESS (2-D gives them per unit thickness), to 1e-6 of
the column family's scale (tests/checkpoint/compare_statistics.py; the
solver's work, the timings, the numbers of DoFs and of contact nodes are not compared). Exits 1 when they do not, or
when the steps differ.

Prints the QOI columns of PLANE (default: none) at the first step, the step
of their largest magnitude and the last step, at 5 significant digits, for
the caller to compare with its expected output."""
import os
import sys

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)),
                                "..", "checkpoint"))
from compare_statistics import (DEFAULT_TOLERANCE, NOT_COMPARED, TOLERANCE,
                                family, read)

PER_THICKNESS = {"force", "energy", "momentum"}
# Sizes of the discretisation: the slab has its third direction (and three
# Q2 nodes across its thickness for each node of the plane: the contact
# node counts, columns ending in _nodes).
SIZES = {"dofs", "cells", "active_cells"}


def main():
    slab_file, plane_file, thickness = sys.argv[1], sys.argv[2], float(sys.argv[3])
    qois = sys.argv[4:]
    slab_head, slab = read(slab_file)
    head, plane = read(plane_file)
    if [r[0] for r in slab] != [r[0] for r in plane]:
        sys.exit(f"FAIL: the steps differ: {len(slab) - 1} in the slab, "
                 f"{len(plane) - 1} in plane strain")
    missing = [c for c in head if c not in slab_head]
    if missing:
        sys.exit(f"FAIL: columns of the plane-strain run missing in the slab's: "
                 f"{missing}")
    column = {c: k for k, c in enumerate(slab_head)}

    def slab_value(row, name):
        v = row[column[name]]
        # Totals are per unit thickness in 2-D; extrema of point values
        # (min_plastic_dissipation [J/m^3], ...) are not totals.
        total = ((family(name) in PER_THICKNESS or name.endswith("_area"))
                 and not name.startswith(("min_", "max_")))
        return v / thickness if total else v

    scale = {}
    for k, name in enumerate(head):
        top = max(abs(r[k]) for r in plane)
        scale[family(name)] = max(scale.get(family(name), 0.), top)
    worst, where = 0., ""
    for k, name in enumerate(head):
        if name in NOT_COMPARED or name in SIZES or name.endswith("_nodes"):
            continue
        s = scale[family(name)] or 1.
        allowed = TOLERANCE.get(family(name), DEFAULT_TOLERANCE)
        for a, b in zip(slab, plane):
            e = abs(slab_value(a, name) - b[k]) / s / allowed
            if e > worst:
                worst, where = e, f"{name} at step {int(b[0])}"
    print(f"the 2-D run against the slab, {len(plane) - 1} steps: "
          + ("the same" if worst <= 1 else "DIFFERENT"))
    for name in qois:
        k = head.index(name)
        values = [r[k] for r in plane]
        largest = max(range(len(values)), key=lambda i: abs(values[i]))
        print(f"{name}: {values[0]:.5g} at step 0, {values[largest]:.5g} "
              f"at step {largest}, {values[-1]:.5g} at step {len(values) - 1}")
    if worst > 1:
        sys.exit(f"FAIL: the runs differ: {worst:.2f} of the tolerance at "
                 f"{where}")
    # The margin goes to the log only: it is round-off.
    print(f"largest difference {worst:.2e} of the tolerance ({where})",
          file=sys.stderr)


if __name__ == "__main__":
    main()
