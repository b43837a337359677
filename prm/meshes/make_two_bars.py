#!/usr/bin/env python3
"""Writes two equal bars on one axis as a Gmsh 2.2 ASCII hexahedral mesh:
the lower one [0, W]^2 x [0, L], the upper one [0, W]^2 x [L + GAP, 2 L +
GAP], each with N cells along z and one across.

Physical tags: volumes 1 (lower), 2 (upper); surfaces 1 the lower bar's
bottom z = 0, 2 the upper bar's top, 3 the lower bar's top (master), 4 the
upper bar's bottom (slave), 5 the side faces normal to x, 6 those normal
to y (both bars).

Usage: make_two_bars.py N L W GAP OUTPUT.msh
"""
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from gmsh_writer import write_gmsh  # noqa: E402

n = int(sys.argv[1])
length = float(sys.argv[2])
width = float(sys.argv[3])
gap = float(sys.argv[4])
out = sys.argv[5]

nodes, elements = [], []


def bar(z0, volume_tag, bottom_tag, top_tag):
    first = len(nodes) + 1

    def nid(i, j, k):
        return first + i + 2 * (j + 2 * k)

    for k in range(n + 1):
        for j in range(2):
            for i in range(2):
                nodes.append((i * width, j * width, z0 + k * length / n))
    for k in range(n):
        v = [nid(0, 0, k), nid(1, 0, k), nid(1, 1, k), nid(0, 1, k),
             nid(0, 0, k + 1), nid(1, 0, k + 1), nid(1, 1, k + 1), nid(0, 1, k + 1)]
        elements.append((5, volume_tag, v))
        if k == 0:
            elements.append((3, bottom_tag, [v[0], v[3], v[2], v[1]]))
        if k == n - 1:
            elements.append((3, top_tag, v[4:]))
        elements.append((3, 5, [v[0], v[4], v[7], v[3]]))
        elements.append((3, 5, [v[1], v[2], v[6], v[5]]))
        elements.append((3, 6, [v[0], v[1], v[5], v[4]]))
        elements.append((3, 6, [v[3], v[7], v[6], v[2]]))


bar(0.0, 1, 1, 3)
bar(length + gap, 2, 4, 2)

write_gmsh(out,
           [(2, 1, "bottom"), (2, 2, "top"), (2, 3, "master"), (2, 4, "slave"),
            (2, 5, "sides x"), (2, 6, "sides y"), (3, 1, "lower"), (3, 2, "upper")],
           nodes, elements)
print(f"{out}: two bars of {n} cells, length {length}, width {width}, gap {gap}")
