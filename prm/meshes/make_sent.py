#!/usr/bin/env python3
"""Writes a single-edge-notched tension (SENT) specimen as a Gmsh 2.2 ASCII
hexahedral mesh: the unit square [0, 1]^2 mm (written in metres) as a thin
slab of thickness t with one element layer, and a slit (duplicated nodes)
along y = 0.5 from the left edge x = 0 to the centre x = 0.5 (validation.md
rung 8, Miehe et al. 2010).

Elements are h (in mm) wide along the crack path (0.5 - band <= x <= XEND,
|y - 0.5| <= band) and grow geometrically (ratio <= 1.25) away from it, so
that the phase field is resolved where the crack runs without hanging nodes.
XEND = 1 (default) resolves the whole path; XEND = 0.5 + band only a box
around the notch tip, enough for the peak force as long as the damage zone
at the peak stays inside the box (check: the peak must not change when the
box grows).

HEIGHT (default 1 mm) makes a taller specimen [0, 1] x [0, HEIGHT] with the
slit at mid-height y = HEIGHT/2 (the ductile notch: its plastic zone must
not reach the grips).

Physical tags: volume 1 (the specimen); surfaces 1 bottom (y = 0), 2 top
(y = HEIGHT), 3 the slab faces z = 0 and z = t, 4 the left and right edges
and the slit faces (traction free).

THICKNESS (default H) sets the slab's thickness (one element layer). For
adaptive refinement note that every refinement halves a cell in all three
directions: a cell refined L times is 2^L layers thick. THICKNESS = 0
writes the plane-strain mesh instead (`set Dimension = 2`): the same
quadrilaterals in the x-y plane, physical surface 1 (the specimen) and
physical curves 1 bottom, 2 top, 4 free edges and slit.

BAND = HEIGHT/2 (with XEND = 1) gives the uniform mesh of h.

TAGS = shear (default: free) tags the edges for the notched shear test:
5 the left and right edges, 6 the lower slit face (both held in y there),
4 the upper slit face only.

Usage: make_sent.py H BAND OUTPUT.msh [XEND [HEIGHT [THICKNESS [TAGS]]]]
       (e.g. make_sent.py 0.0075 0.05 sent.msh)
"""
import sys

from gmsh_writer import write_gmsh

h = float(sys.argv[1]) if len(sys.argv) > 1 else 0.0075
band = float(sys.argv[2]) if len(sys.argv) > 2 else 0.05
out = sys.argv[3] if len(sys.argv) > 3 else "sent.msh"
x_end = float(sys.argv[4]) if len(sys.argv) > 4 else 1.0
height = float(sys.argv[5]) if len(sys.argv) > 5 else 1.0
y_mid = 0.5 * height
mm = 1e-3
thickness = float(sys.argv[6]) if len(sys.argv) > 6 else h
tags = sys.argv[7] if len(sys.argv) > 7 else "free"
if tags not in ("free", "shear"):
    sys.exit(f"make_sent.py: TAGS = '{tags}': 'free' or 'shear'")
shear = tags == "shear"


def graded(a, b, h_fine, fine_from_a):
    """Points from a to b, spacing h_fine at the fine end, growing by at
    most 1.25 per element towards the other end."""
    length = b - a
    if length <= 1e-12:
        return [a]
    sizes = []
    size, total = h_fine, 0.0
    while total + size < length - 1e-12:
        sizes.append(size)
        total += size
        size = min(size * 1.25, 0.1)
    # stretch the sizes to fill the interval exactly
    scale = length / sum(sizes) if sizes else 1.0
    sizes = [s * scale for s in sizes] if sizes else [length]
    if not fine_from_a:
        sizes = sizes[::-1]
    pts = [a]
    for s in sizes:
        pts.append(pts[-1] + s)
    pts[-1] = b
    return pts


def uniform(a, b, h_fine):
    n = max(1, round((b - a) / h_fine))
    return [a + (b - a) * i / n for i in range(n + 1)]


# x: graded up to 0.5 - band, uniform (fine) to x_end, graded to 1; the
# slit's tip x = 0.5 is a grid line whatever h (spacings near h on either
# side of it), so the notch has the same length on every mesh
x0 = 0.5 - band
xs = graded(0.0, x0, h, False)[:-1] + uniform(x0, 0.5, h)
if x_end > 0.5 + 1e-12:
    xs += uniform(0.5, x_end, h)[1:]
if x_end < 1.0 - 1e-12:
    xs += graded(x_end, 1.0, h, True)[1:]
# y: uniform in the band around y_mid (a grid line), graded outside
ylo = graded(0.0, y_mid - band, h, False)[:-1] + uniform(y_mid - band, y_mid, h)
yhi = (uniform(y_mid, y_mid + band, h)[1:]
       + graded(y_mid + band, height, h, True)[1:])
ys = ylo + yhi
zs = [0.0, thickness]
j_slit = ys.index(y_mid)
nx, ny = len(xs), len(ys)

node_id = {}
nodes = []


def node(i, j, k, upper):
    """Node at grid point (i, j, k); on the slit (j = j_slit, x < 0.5) the
    upper side gets its own copy."""
    dup = upper and j == j_slit and xs[i] < 0.5 - 1e-12
    key = (i, j, k, dup)
    if key not in node_id:
        node_id[key] = len(nodes) + 1
        nodes.append((xs[i] * mm, ys[j] * mm, zs[k] * mm))
    return node_id[key]


two_d = thickness == 0.0
elements = []
for j in range(ny - 1):
    upper = j >= j_slit
    for i in range(nx - 1):
        v = [node(i, j, 0, upper), node(i + 1, j, 0, upper),
             node(i + 1, j + 1, 0, upper), node(i, j + 1, 0, upper)]
        if two_d:
            # the quadrilateral and its boundary lines (type 1), each edge
            # as (first, second) of v: bottom 0-1, right 1-2, top 3-2, left 0-3
            elements.append((3, 1, v))
            edges = {"bottom": [v[0], v[1]], "top": [v[3], v[2]],
                     "left": [v[0], v[3]], "right": [v[1], v[2]]}
            etype = 1
        else:
            v += [node(i, j, 1, upper), node(i + 1, j, 1, upper),
                  node(i + 1, j + 1, 1, upper), node(i, j + 1, 1, upper)]
            elements.append((5, 1, v))
            # slab faces
            elements.append((3, 3, v[:4]))
            elements.append((3, 3, v[4:]))
            edges = {"bottom": [v[0], v[1], v[5], v[4]],
                     "top": [v[3], v[2], v[6], v[7]],
                     "left": [v[0], v[3], v[7], v[4]],
                     "right": [v[1], v[2], v[6], v[5]]}
            etype = 3
        if j == 0:
            elements.append((etype, 1, edges["bottom"]))
        if j == ny - 2:
            elements.append((etype, 2, edges["top"]))
        if i == 0:
            elements.append((etype, 5 if shear else 4, edges["left"]))
        if i == nx - 2:
            elements.append((etype, 5 if shear else 4, edges["right"]))
        # slit faces: the bottom of the upper row and the top of the lower row
        if xs[i + 1] <= 0.5 + 1e-12:
            if j == j_slit:
                elements.append((etype, 4, edges["bottom"]))
            if j == j_slit - 1:
                elements.append((etype, 6 if shear else 4, edges["top"]))

if two_d:
    names = [(1, 1, "bottom"), (1, 2, "top"), (1, 4, "free edges and slit"),
             (2, 1, "specimen")]
else:
    names = [(2, 1, "bottom"), (2, 2, "top"), (2, 3, "slab faces"),
             (2, 4, "free edges and slit"), (3, 1, "specimen")]
if shear:
    names[2] = (names[2][0], 4, "upper slit face")
    names[-1:-1] = [(names[2][0], 5, "left and right edges"),
                    (names[2][0], 6, "lower slit face")]
write_gmsh(out, names, nodes, elements, digits=15)
cells = len([e for e in elements if e[0] == (3 if two_d else 5)])
print(f"{out}: {cells} {'quadrilaterals' if two_d else 'hexahedra'}, "
      f"{len(nodes)} nodes, h = {h} mm for {0.5 - band} <= x <= {x_end}, "
      f"|y - {y_mid}| <= {band}")
