#!/usr/bin/env python3
"""Writes the plane-strain contact patch test (tests/two_d/contact_patch) as
a Gmsh 2.2 ASCII quadrilateral mesh: two unit squares stacked along y, the
lower one [0, 1] x [0, 1] with 3 x 2 cells, the upper one [0, 1] x [1, 2]
with 4 x 2 cells, their columns at unequal spacings so that the two contact
lines do not match (no node of one lies on a node of the other).

Physical tags: areas 1 (lower), 2 (upper); lines 1 bottom y = 0, 2 top
y = 2, 3 lower body's top y = 1 (master), 4 upper body's bottom y = 1
(slave), 5 and 8 the faces x = 0 of the lower and the upper body, 7 the
faces x = 1.

Usage: make_contact_patch_2d.py OUTPUT.msh
"""
import os
import sys

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "prm", "meshes"))
from gmsh_writer import column_body, write_gmsh  # noqa: E402

out = sys.argv[1] if len(sys.argv) > 1 else "contact_patch_2d.msh"
nodes, elements = [], []
column_body(nodes, elements, [0.0, 0.3, 0.7, 1.0],
            [(lambda x, y=y: y) for y in (0.0, 0.5, 1.0)], None, 1,
            dict(bottom=1, top=3, left=5, right=7))
column_body(nodes, elements, [0.0, 0.2, 0.45, 0.8, 1.0],
            [(lambda x, y=y: y) for y in (1.0, 1.5, 2.0)], None, 2,
            dict(bottom=4, top=2, left=8, right=7))
write_gmsh(out,
           [(1, 1, "bottom"), (1, 2, "top"), (1, 3, "lower top"), (1, 4, "upper bottom"),
            (1, 5, "lower x = 0"), (1, 7, "x = 1"), (1, 8, "upper x = 0"),
            (2, 1, "lower"), (2, 2, "upper")],
           nodes, elements)
print(f"{out}: {sum(1 for e in elements if e[0] == 3)} quadrilaterals")
