"""Reads one step of a run's HDF5 output (Output/Format = hdf5: the series
solution.xdmf, the mesh in mesh_NNNNN.h5, the fields in solution_NNNNN.h5)
into a vtkUnstructuredGrid with the fields as point data, for the scripts
that draw results without ParaView (VTK's Python wrapping in Debian has no
XDMF reader). Needs python3-h5py and python3-vtk9."""
import os
import sys
import xml.etree.ElementTree as ET

import numpy as np
import vtk
from vtk.util import numpy_support

# XDMF topology names of deal.II's output -> VTK cell type.
cell_types = {"Hexahedron": vtk.VTK_HEXAHEDRON, "Quadrilateral": vtk.VTK_QUAD,
              "Polyline": vtk.VTK_LINE}


def steps(xdmf):
    """[(time, grid element)] of the series in @p xdmf, in order."""
    grids = [g for g in ET.parse(xdmf).getroot().iter("Grid")
             if g.find("Time") is not None]
    if not grids:
        sys.exit(f"error: {xdmf} lists no output step")
    return [(float(g.find("Time").get("Value")), g) for g in grids]


def dataset(folder, item):
    """The array a DataItem 'file.h5:/name' points to."""
    import h5py
    file_name, name = item.text.strip().split(":")
    with h5py.File(os.path.join(folder, file_name), "r") as f:
        return np.array(f[name])


def read(xdmf, step=None):
    """(grid, time) of output step @p step (the last if None)."""
    folder = os.path.dirname(os.path.abspath(xdmf))
    time, grid = steps(xdmf)[-1 if step is None else step]
    points = dataset(folder, grid.find("Geometry/DataItem"))
    topology = grid.find("Topology")
    cells = dataset(folder, topology.find("DataItem")).astype(np.int64)
    kind = cell_types[topology.get("TopologyType")]

    result = vtk.vtkUnstructuredGrid()
    vtk_points = vtk.vtkPoints()
    vtk_points.SetData(numpy_support.numpy_to_vtk(
        np.ascontiguousarray(points.reshape(len(points), -1), dtype=float),
        deep=True))
    result.SetPoints(vtk_points)
    n = cells.shape[1]
    connectivity = np.hstack([np.full((len(cells), 1), n), cells]).ravel()
    cell_array = vtk.vtkCellArray()
    cell_array.SetCells(len(cells), numpy_support.numpy_to_vtkIdTypeArray(
        connectivity, deep=True))
    result.SetCells(kind, cell_array)
    for attribute in grid.findall("Attribute"):
        values = dataset(folder, attribute.find("DataItem"))
        array = numpy_support.numpy_to_vtk(
            np.ascontiguousarray(values.reshape(len(values), -1), dtype=float),
            deep=True)
        array.SetName(attribute.get("Name"))
        result.GetPointData().AddArray(array)
    return result, time


class Source:
    """A grid behind the two calls of a VTK reader the drawing scripts
    use: GetOutput() and GetOutputPort()."""

    def __init__(self, grid):
        self.producer = vtk.vtkTrivialProducer()
        self.producer.SetOutput(grid)
        self.grid = grid

    def GetOutput(self):
        return self.grid

    def GetOutputPort(self):
        return self.producer.GetOutputPort()
