#!/usr/bin/env python3
"""Writes the contact patch test (validation.md rung 10, contact.md) as a
Gmsh 2.2 ASCII hexahedral mesh: two unit cubes stacked along z, the lower
one [0, 1]^2 x [0, 1] with N_LOW^2 x 2 cells, the upper one [0, 1]^2 x
[1, 2] with N_UP^2 x 2 cells. Inside each square the in-plane node
positions are swirled (rotated about the centre by an angle that vanishes
on the square's edges, ANGLE degrees at the centre, opposite senses in the
two bodies), so the two contact surfaces do not match and their element
edges cross at angles.

Physical tags: volumes 1 (lower), 2 (upper); surfaces 1 bottom z = 0,
2 top z = 2, 3 lower body's top z = 1 (master), 4 upper body's bottom z = 1
(slave), 5 and 6 the lower body's faces x = 0 and y = 0, 8 and 9 the
upper body's, 7 the other side faces.

Usage: make_contact_patch.py N_LOW N_UP ANGLE OUTPUT.msh
"""
import math
import os
import sys

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "prm", "meshes"))
from gmsh_writer import write_gmsh  # noqa: E402

n_low = int(sys.argv[1]) if len(sys.argv) > 1 else 3
n_up = int(sys.argv[2]) if len(sys.argv) > 2 else 4
angle = float(sys.argv[3]) if len(sys.argv) > 3 else 10.0
out = sys.argv[4] if len(sys.argv) > 4 else "contact_patch.msh"

nodes, elements = [], []


def swirl(x, y, degrees):
    # rotation about (0.5, 0.5) by degrees * b(x, y), b = 1 at the centre
    # and 0 on the edges of the square
    b = (16 * x * (1 - x) * y * (1 - y)) ** 2
    a = math.radians(degrees) * b
    dx, dy = x - 0.5, y - 0.5
    return (0.5 + math.cos(a) * dx - math.sin(a) * dy,
            0.5 + math.sin(a) * dx + math.cos(a) * dy)


def block(n, z0, degrees, volume_tag, top_tag, bottom_tag, x0_tag, y0_tag):
    nz = 2
    first = len(nodes) + 1

    def nid(i, j, k):
        return first + i + (n + 1) * (j + (n + 1) * k)

    for k in range(nz + 1):
        for j in range(n + 1):
            for i in range(n + 1):
                x, y = swirl(i / n, j / n, degrees)
                nodes.append((x, y, z0 + k / nz))
    for k in range(nz):
        for j in range(n):
            for i in range(n):
                v = [nid(i, j, k), nid(i + 1, j, k), nid(i + 1, j + 1, k),
                     nid(i, j + 1, k), nid(i, j, k + 1), nid(i + 1, j, k + 1),
                     nid(i + 1, j + 1, k + 1), nid(i, j + 1, k + 1)]
                elements.append((5, volume_tag, v))
                if k == 0:
                    elements.append((3, bottom_tag, [v[0], v[3], v[2], v[1]]))
                if k == nz - 1:
                    elements.append((3, top_tag, v[4:]))
                if i == 0:
                    elements.append((3, x0_tag, [v[0], v[4], v[7], v[3]]))
                if i == n - 1:
                    elements.append((3, 7, [v[1], v[2], v[6], v[5]]))
                if j == 0:
                    elements.append((3, y0_tag, [v[0], v[1], v[5], v[4]]))
                if j == n - 1:
                    elements.append((3, 7, [v[3], v[7], v[6], v[2]]))


block(n_low, 0.0, angle, 1, 3, 1, 5, 6)
block(n_up, 1.0, -angle, 2, 2, 4, 8, 9)

write_gmsh(out,
           [(2, 1, "bottom"), (2, 2, "top"), (2, 3, "master"), (2, 4, "slave"),
            (2, 5, "x0 lower"), (2, 6, "y0 lower"), (2, 7, "free"), (2, 8, "x0 upper"),
            (2, 9, "y0 upper"), (3, 1, "lower"), (3, 2, "upper")],
           nodes, elements)
print(f"{out}: lower {n_low}x{n_low}x2, upper {n_up}x{n_up}x2 cells, "
      f"swirl {angle} degrees")
