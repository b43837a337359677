#!/usr/bin/env python3
"""Writes the Hertz sphere test (validation.md rung 11, contact.md) as a
Gmsh 2.2 ASCII hexahedral mesh: a spherical indenter of radius R on a flat
foundation, quarter model x >= 0, y >= 0 (symmetry planes x = 0, y = 0).
All lengths in metres.

Foundation (volume 1): [0, W]^2 x [-W, 0]. Indenter (volume 2): over
[0, W]^2, from its surface z = R - sqrt(R^2 - x^2 - y^2) up to z = W (it
touches the foundation at the origin). Elements are h wide for x, y <= 1.5 a
and |z| <= a (a: the expected contact radius), then grow geometrically
(ratio <= GROWTH) to the outer faces. Both bodies share the columns of the
grid; the indenter's nodes are placed along vertical lines, its surface
nodes exactly on the sphere, so the contact surfaces do not match.

Physical tags: surfaces 1 foundation bottom z = -W, 2 indenter top z = W,
3 foundation top z = 0 (master), 4 indenter surface (slave), 5 the faces
x = 0 of both bodies, 6 the faces y = 0, 7 the faces x = W and y = W.

Usage: make_hertz_sphere.py R A H_OVER_A W GROWTH OUTPUT.msh
       (e.g. make_hertz_sphere.py 1 0.01 4 0.2 1.5 hertz_sphere.msh: h = a/4)
"""
import math
import sys

from gmsh_writer import block_body, graded, write_gmsh

R = float(sys.argv[1]) if len(sys.argv) > 1 else 1.0
a = float(sys.argv[2]) if len(sys.argv) > 2 else 0.01
ratio = float(sys.argv[3]) if len(sys.argv) > 3 else 4
W = float(sys.argv[4]) if len(sys.argv) > 4 else 0.2
growth = float(sys.argv[5]) if len(sys.argv) > 5 else 1.5
out = sys.argv[6] if len(sys.argv) > 6 else "hertz_sphere.msh"
h = a / ratio
assert W < R / 2, "the cap must stay well inside the sphere"

xs = graded(h, 1.5 * a, W, growth)
ds = graded(h, a, W, growth)  # depth below / height above the contact point
nodes, elements = [], []


def body(levels, volume, bottom_tag, top_tag):
    block_body(nodes, elements, xs, xs, levels, volume,
               dict(bottom=bottom_tag, top=top_tag, x0=5, y0=6, x1=7, y1=7))


def surface(x, y):
    return R - math.sqrt(R * R - x * x - y * y)


# Foundation: levels from z = -W up to 0; indenter: from the sphere up to W.
body([(lambda x, y, d=d: -d) for d in reversed(ds)], 1, 1, 3)
body([(lambda x, y, d=d: surface(x, y) + d * (1 - surface(x, y) / W)) for d in ds], 2, 4, 2)

write_gmsh(out,
           [(2, 1, "foundation bottom"), (2, 2, "indenter top"), (2, 3, "foundation top"),
            (2, 4, "indenter surface"), (2, 5, "symmetry x"), (2, 6, "symmetry y"),
            (2, 7, "outer"), (3, 1, "foundation"), (3, 2, "indenter")],
           nodes, elements)
cells = 2 * (len(xs) - 1) ** 2 * (len(ds) - 1)
print(f"{out}: {cells} hexahedra, {len(xs) - 1}^2 x {len(ds) - 1} per body (h = {h:g} m, "
      f"R = {R}, a = {a}, W = {W}), ~{3 * 2 * (2 * len(xs) - 1) ** 2 * (2 * len(ds) - 1)} Q2 unknowns")
