"""Shared by the mesh generators: writes hexahedral meshes as Gmsh 2.2 ASCII
files, the format the 'gmsh' scene reads (deal.II GridIn::read_msh), and
meshes plane-strain bodies column by column (column_body) and 3-D bodies
over a grid of columns (block_body); graded() spaces the grid lines.

nodes: list of (x, y, z), numbered from 1 in list order.
elements: list of (gmsh_type, physical_tag, [node numbers]); type 5 is an
  8-node hexahedron (a body; its tag becomes the cell's material id), type 3
  a 4-node quadrilateral (a boundary face; its tag becomes the boundary id).
names: list of (dimension, tag, name) for the $PhysicalNames block.
"""


def write_gmsh(path, names, nodes, elements, digits=17):
    with open(path, "w") as f:
        f.write("$MeshFormat\n2.2 0 8\n$EndMeshFormat\n")
        f.write(f"$PhysicalNames\n{len(names)}\n")
        for dimension, tag, name in names:
            f.write(f'{dimension} {tag} "{name}"\n')
        f.write("$EndPhysicalNames\n")
        f.write(f"$Nodes\n{len(nodes)}\n")
        for i, (x, y, z) in enumerate(nodes, start=1):
            f.write(f"{i} {x:.{digits}g} {y:.{digits}g} {z:.{digits}g}\n")
        f.write("$EndNodes\n")
        f.write(f"$Elements\n{len(elements)}\n")
        for e, (etype, tag, v) in enumerate(elements, start=1):
            f.write(f"{e} {etype} 2 {tag} {tag} " + " ".join(map(str, v)) + "\n")
        f.write("$EndElements\n")


def column_body(nodes, elements, xs, levels, zs, volume, faces):
    """Appends one body of a plane-strain slab (one element layer between
    zs[0] and zs[1]) meshed by the columns xs and the curves levels[j](x)
    (bottom to top): nodes and hexahedra with volume tag `volume`, and the
    boundary quadrilaterals with the tags faces["z"] (both slab faces),
    faces["bottom"], faces["top"], faces["left"] (x = xs[0]) and
    faces["right"] (x = xs[-1]). With zs = None the body is 2-D:
    quadrilaterals (type 3) with boundary lines (type 1) of the same tags
    (no "z")."""
    if zs is None:
        column_body_2d(nodes, elements, xs, levels, volume, faces)
        return
    first = len(nodes) + 1
    nx, ny = len(xs), len(levels)

    def nid(i, j, k):
        return first + i + nx * (j + ny * k)

    for k in range(2):
        for j in range(ny):
            for i in range(nx):
                nodes.append((xs[i], levels[j](xs[i]), zs[k]))
    for j in range(ny - 1):
        for i in range(nx - 1):
            v = [nid(i, j, 0), nid(i + 1, j, 0), nid(i + 1, j + 1, 0), nid(i, j + 1, 0),
                 nid(i, j, 1), nid(i + 1, j, 1), nid(i + 1, j + 1, 1), nid(i, j + 1, 1)]
            elements.append((5, volume, v))
            elements.append((3, faces["z"], v[:4]))
            elements.append((3, faces["z"], v[4:]))
            if j == 0:
                elements.append((3, faces["bottom"], [v[0], v[1], v[5], v[4]]))
            if j == ny - 2:
                elements.append((3, faces["top"], [v[3], v[2], v[6], v[7]]))
            if i == 0:
                elements.append((3, faces["left"], [v[0], v[3], v[7], v[4]]))
            if i == nx - 2:
                elements.append((3, faces["right"], [v[1], v[2], v[6], v[5]]))


def column_body_2d(nodes, elements, xs, levels, volume, faces):
    """column_body() in the plane (z = 0): quadrilaterals counter-clockwise
    and their boundary lines."""
    first = len(nodes) + 1
    nx, ny = len(xs), len(levels)

    def nid(i, j):
        return first + i + nx * j

    for j in range(ny):
        for i in range(nx):
            nodes.append((xs[i], levels[j](xs[i]), 0.0))
    for j in range(ny - 1):
        for i in range(nx - 1):
            v = [nid(i, j), nid(i + 1, j), nid(i + 1, j + 1), nid(i, j + 1)]
            elements.append((3, volume, v))
            if j == 0:
                elements.append((1, faces["bottom"], [v[0], v[1]]))
            if j == ny - 2:
                elements.append((1, faces["top"], [v[3], v[2]]))
            if i == 0:
                elements.append((1, faces["left"], [v[0], v[3]]))
            if i == nx - 2:
                elements.append((1, faces["right"], [v[1], v[2]]))


def block_body(nodes, elements, xs, ys, levels, volume, faces):
    """Appends one 3-D body meshed by the columns over the grid xs x ys and
    the surfaces levels[k](x, y) (bottom to top): nodes and hexahedra with
    volume tag `volume`, and the boundary quadrilaterals with the tags
    faces["bottom"], faces["top"], faces["x0"] (x = xs[0]), faces["x1"]
    (x = xs[-1]), faces["y0"] and faces["y1"]. Faces are oriented with the
    outward normal by the right-hand rule."""
    first = len(nodes) + 1
    nx, ny, nz = len(xs), len(ys), len(levels)

    def nid(i, j, k):
        return first + i + nx * (j + ny * k)

    for k in range(nz):
        for j in range(ny):
            for i in range(nx):
                nodes.append((xs[i], ys[j], levels[k](xs[i], ys[j])))
    for k in range(nz - 1):
        for j in range(ny - 1):
            for i in range(nx - 1):
                v = [nid(i, j, k), nid(i + 1, j, k), nid(i + 1, j + 1, k), nid(i, j + 1, k),
                     nid(i, j, k + 1), nid(i + 1, j, k + 1), nid(i + 1, j + 1, k + 1),
                     nid(i, j + 1, k + 1)]
                elements.append((5, volume, v))
                if k == 0:
                    elements.append((3, faces["bottom"], [v[0], v[3], v[2], v[1]]))
                if k == nz - 2:
                    elements.append((3, faces["top"], v[4:]))
                if i == 0:
                    elements.append((3, faces["x0"], [v[0], v[4], v[7], v[3]]))
                if i == nx - 2:
                    elements.append((3, faces["x1"], [v[1], v[2], v[6], v[5]]))
                if j == 0:
                    elements.append((3, faces["y0"], [v[0], v[1], v[5], v[4]]))
                if j == ny - 2:
                    elements.append((3, faces["y1"], [v[3], v[7], v[6], v[2]]))


def graded(h, length_fine, total, growth):
    """Offsets 0 .. total: spacing h up to length_fine, then growing by
    `growth` per element (the last ones stretched to end at total)."""
    n = max(1, round(length_fine / h))
    pts = [length_fine * i / n for i in range(n + 1)]
    size = h
    tail = []
    while pts[-1] + sum(tail) + size * growth < total - 1e-12:
        size *= growth
        tail.append(size)
    scale = (total - pts[-1]) / sum(tail) if tail else 1.0
    for s in tail:
        pts.append(pts[-1] + s * scale)
    pts[-1] = total
    return pts
