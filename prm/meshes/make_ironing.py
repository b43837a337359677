#!/usr/bin/env python3
"""Writes the ironing scene (validation.md rung 13) as a Gmsh 2.2 hexahedral
mesh: a stiff die with a circular bottom (radius R) on a soft slab, plane
strain as one element layer of thickness T_Z. All lengths in metres.

Slab (volume 1): [0, L] x [-D, 0], elements H_SLAB (the finer mesh: the
slab's top is the slave surface). Die (volume 2): x in [X0 - W, X0 + W],
from its bottom y = R - sqrt(R^2 - (x - X0)^2) (touching the slab at
x = X0) up to y = HD, elements H_DIE, nodes along vertical lines, the
bottom nodes exactly on the circle.

Physical tags: surfaces 1 slab bottom, 2 die top, 3 slab top (slave),
4 die bottom (master), 5 the slab faces z = 0 and z = T_Z of both bodies,
6 the remaining sides (free).

Usage: make_ironing.py H_SLAB H_DIE OUTPUT.msh [2d]
       (L = 0.06, D = 0.006, R = 0.03, W = 0.01, X0 = 0.02, HD = 0.01,
       T_Z = H_DIE)
With the last argument 2d the mesh is plane (Dimension = 2): quadrilaterals
with boundary lines of the same tags (no 5).
"""
import math
import sys

from gmsh_writer import column_body, write_gmsh

h_slab = float(sys.argv[1]) if len(sys.argv) > 1 else 0.001
h_die = float(sys.argv[2]) if len(sys.argv) > 2 else 0.002
out = sys.argv[3] if len(sys.argv) > 3 else "ironing.msh"
L, D, R, W, X0, HD = 0.06, 0.006, 0.03, 0.01, 0.02, 0.01
two_d = len(sys.argv) > 4 and sys.argv[4] == "2d"
zs = None if two_d else [0.0, h_die]
nodes, elements = [], []


def divide(a, b, h):
    n = max(1, round((b - a) / h))
    return [a + (b - a) * i / n for i in range(n + 1)]


def body(xs, levels, volume, bottom_tag, top_tag):
    column_body(nodes, elements, xs, levels, zs, volume,
                dict(z=5, bottom=bottom_tag, top=top_tag, left=6, right=6))


# Slab: levels from y = -D up to 0.
body(divide(0.0, L, h_slab),
     [(lambda x, y=y: y) for y in divide(-D, 0.0, h_slab)], 1, 1, 3)


def bottom(x):
    return R - math.sqrt(R * R - (x - X0) ** 2)


# Die: from the circle up to HD along vertical lines.
body(divide(X0 - W, X0 + W, h_die),
     [(lambda x, s=s: bottom(x) + s * (HD - bottom(x))) for s in divide(0.0, 1.0, h_die / HD)],
     2, 4, 2)

if two_d:
    names = [(1, 1, "slab bottom"), (1, 2, "die top"), (1, 3, "slab top"),
             (1, 4, "die bottom"), (1, 6, "sides"), (2, 1, "slab"), (2, 2, "die")]
else:
    names = [(2, 1, "slab bottom"), (2, 2, "die top"), (2, 3, "slab top"),
             (2, 4, "die bottom"), (2, 5, "slab faces"), (2, 6, "sides"),
             (3, 1, "slab"), (3, 2, "die")]
write_gmsh(out, names, nodes, elements)
cell = 3 if two_d else 5
print(f"{out}: {sum(1 for e in elements if e[0] == cell)} "
      f"{'quadrilaterals' if two_d else 'hexahedra'} "
      f"(slab h = {h_slab:g} m, die h = {h_die:g} m)")
