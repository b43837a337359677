#!/usr/bin/env python3
"""Writes the Hertz line-contact test (validation.md rung 11, contact.md) as
a Gmsh 2.2 ASCII hexahedral mesh: a cylindrical indenter of radius R on a
flat foundation, plane strain as a slab of one element layer (thickness =
the element size h at the contact), half model x >= 0 (symmetry plane
x = 0). All lengths in metres.

Foundation (volume 1): [0, W] x [-H, 0]. Indenter (volume 2): x in [0, W],
from its surface y = R - sqrt(R^2 - x^2) up to y = H (it touches the
foundation at the origin). Elements are h wide for x <= 3 a and |y| <= 2 a
(a: the expected contact half-width), then grow geometrically (ratio
<= 1.25) to the outer faces. The indenter's nodes are placed along
vertical lines, the surface nodes exactly on the circle.

Physical tags: surfaces 1 foundation bottom y = -H, 2 indenter top y = H,
3 foundation top y = 0 (master), 4 indenter surface (slave), 5 the faces
x = 0 of both bodies, 6 the slab faces z = 0 and z = h, 7 the faces x = W.

Usage: make_hertz.py R A H_OVER_A W OUTPUT.msh [2d]
       (e.g. make_hertz.py 1 0.01 8 0.3 hertz.msh: h = a/8)
With the last argument 2d the mesh is plane (Dimension = 2): quadrilaterals
with boundary lines of the same tags (no 6).
"""
import math
import sys

from gmsh_writer import column_body, graded, write_gmsh

R = float(sys.argv[1]) if len(sys.argv) > 1 else 1.0
a = float(sys.argv[2]) if len(sys.argv) > 2 else 0.01
ratio = float(sys.argv[3]) if len(sys.argv) > 3 else 8
W = float(sys.argv[4]) if len(sys.argv) > 4 else 0.3
out = sys.argv[5] if len(sys.argv) > 5 else "hertz.msh"
two_d = len(sys.argv) > 6 and sys.argv[6] == "2d"
h = a / ratio
H = W

xs = graded(h, 3 * a, W, 1.25)
ds = graded(h, 2 * a, H, 1.25)  # depth below / height above the contact point
zs = None if two_d else [0.0, h]
nodes, elements = [], []


def body(levels, volume, bottom_tag, top_tag):
    column_body(nodes, elements, xs, levels, zs, volume,
                dict(z=6, bottom=bottom_tag, top=top_tag, left=5, right=7))


# Foundation: levels from y = -H up to 0.
body([(lambda x, d=d: -d) for d in reversed(ds)], 1, 1, 3)


# Indenter: from the circle up to H along vertical lines.
def surface(x):
    return R - math.sqrt(R * R - x * x)


body([(lambda x, d=d: surface(x) + d * (1 - surface(x) / H)) for d in ds], 2, 4, 2)

if two_d:
    names = [(1, 1, "foundation bottom"), (1, 2, "indenter top"), (1, 3, "foundation top"),
             (1, 4, "indenter surface"), (1, 5, "symmetry"), (1, 7, "outer"),
             (2, 1, "foundation"), (2, 2, "indenter")]
else:
    names = [(2, 1, "foundation bottom"), (2, 2, "indenter top"), (2, 3, "foundation top"),
             (2, 4, "indenter surface"), (2, 5, "symmetry"), (2, 6, "slab faces"),
             (2, 7, "outer"), (3, 1, "foundation"), (3, 2, "indenter")]
write_gmsh(out, names, nodes, elements)
print(f"{out}: {len(xs) - 1} x {2 * (len(ds) - 1)} "
      f"{'quadrilaterals' if two_d else 'hexahedra'} (h = {h:g} m, "
      f"R = {R}, a = {a}, W = H = {W})")
