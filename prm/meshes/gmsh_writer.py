"""Shared by the mesh generators: writes hexahedral meshes as Gmsh 2.2 ASCII
files, the format the 'gmsh' scene reads (deal.II GridIn::read_msh).

nodes: list of (x, y, z), numbered from 1 in list order.
elements: list of (gmsh_type, physical_tag, [node numbers]); type 5 is an
  8-node hexahedron (a body; its tag becomes the cell's material id), type 3
  a 4-node quadrilateral (a boundary face; its tag becomes the boundary id).
names: list of (dimension, tag, name) for the $PhysicalNames block.
"""


def write_gmsh(path, names, nodes, elements):
    with open(path, "w") as f:
        f.write("$MeshFormat\n2.2 0 8\n$EndMeshFormat\n")
        f.write(f"$PhysicalNames\n{len(names)}\n")
        for dimension, tag, name in names:
            f.write(f'{dimension} {tag} "{name}"\n')
        f.write("$EndPhysicalNames\n")
        f.write(f"$Nodes\n{len(nodes)}\n")
        for i, (x, y, z) in enumerate(nodes, start=1):
            f.write(f"{i} {x:.17g} {y:.17g} {z:.17g}\n")
        f.write("$EndNodes\n")
        f.write(f"$Elements\n{len(elements)}\n")
        for e, (etype, tag, v) in enumerate(elements, start=1):
            f.write(f"{e} {etype} 2 {tag} {tag} " + " ".join(map(str, v)) + "\n")
        f.write("$EndElements\n")
