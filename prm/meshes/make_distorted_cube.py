#!/usr/bin/env python3
"""Writes distorted_cube.msh (Gmsh 2.2 ASCII): the unit cube as 3x3x3
hexahedra whose interior vertices are moved by up to 0.1 (a fixed,
reproducible pattern), physical volume 7 (the body's material id) and
physical surfaces 1..6 on the faces x-, x+, y-, y+, z-, z+ (boundary ids).
Used by the patch test tests/distorted_patch.cc and the scene prm/gmsh_distorted_cube.prm."""

n = 3
def index(i, j, k):
    return 1 + i + (n + 1) * (j + (n + 1) * k)

nodes = []
for k in range(n + 1):
    for j in range(n + 1):
        for i in range(n + 1):
            x, y, z = i / n, j / n, k / n
            if 0 < i < n and 0 < j < n and 0 < k < n:
                # deterministic distortion of interior vertices
                x += 0.1 * ((i * 7 + j * 3 + k * 5) % 5 - 2) / 2
                y += 0.1 * ((i * 2 + j * 5 + k * 3) % 5 - 2) / 2
                z += 0.1 * ((i * 3 + j * 2 + k * 7) % 5 - 2) / 2
            nodes.append((index(i, j, k), x, y, z))

elements = []
# boundary quads: (physical tag, 4 nodes)
def quad(tag, a, b, c, d):
    elements.append((3, tag, [a, b, c, d]))
for a in range(n):
    for b in range(n):
        quad(1, index(0, a, b), index(0, a + 1, b), index(0, a + 1, b + 1), index(0, a, b + 1))
        quad(2, index(n, a, b), index(n, a + 1, b), index(n, a + 1, b + 1), index(n, a, b + 1))
        quad(3, index(a, 0, b), index(a + 1, 0, b), index(a + 1, 0, b + 1), index(a, 0, b + 1))
        quad(4, index(a, n, b), index(a + 1, n, b), index(a + 1, n, b + 1), index(a, n, b + 1))
        quad(5, index(a, b, 0), index(a + 1, b, 0), index(a + 1, b + 1, 0), index(a, b + 1, 0))
        quad(6, index(a, b, n), index(a + 1, b, n), index(a + 1, b + 1, n), index(a, b + 1, n))
for k in range(n):
    for j in range(n):
        for i in range(n):
            # Gmsh hexahedron: bottom face counter-clockwise, then top face
            v = [index(i, j, k), index(i + 1, j, k), index(i + 1, j + 1, k), index(i, j + 1, k)]
            v += [index(i, j, k + 1), index(i + 1, j, k + 1), index(i + 1, j + 1, k + 1), index(i, j + 1, k + 1)]
            elements.append((5, 7, v))

with open("distorted_cube.msh", "w") as f:
    f.write("$MeshFormat\n2.2 0 8\n$EndMeshFormat\n")
    f.write("$PhysicalNames\n7\n")
    for tag, name in zip(range(1, 7), ["xmin", "xmax", "ymin", "ymax", "zmin", "zmax"]):
        f.write(f'2 {tag} "{name}"\n')
    f.write('3 7 "body"\n$EndPhysicalNames\n')
    f.write(f"$Nodes\n{len(nodes)}\n")
    for idx, x, y, z in nodes:
        f.write(f"{idx} {x:.12g} {y:.12g} {z:.12g}\n")
    f.write("$EndNodes\n")
    f.write(f"$Elements\n{len(elements)}\n")
    for e, (etype, tag, v) in enumerate(elements, start=1):
        f.write(f"{e} {etype} 2 {tag} {tag} " + " ".join(map(str, v)) + "\n")
    f.write("$EndElements\n")
