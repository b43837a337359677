#!/usr/bin/python3
"""Off-screen 3-D pictures of a run's last output step: the deformed bodies
coloured by chosen fields, one PNG per field (no ParaView needed).

Usage: scripts/render_fields.py RESULTS [FIELD ...] [--body ID] [--warp F]
                                [--step N] [--out PREFIX]
  RESULTS  a results directory holding solution.pvd or, from Output/Format =
           hdf5, solution.xdmf (or the .pvd or .xdmf itself)
  FIELD    point-data arrays of the output (default: s alpha)
  --body   colour only the body with this material id (default 0); the other
           bodies are drawn in light grey
  --warp   displacement magnification (default 1: the true deformed shape)
  --step   the output step to draw (default: the last one)
  --out    where to write: PREFIX + FIELD + .png (default: RESULTS/)
Writes RESULTS/FIELD.png (or PREFIX + FIELD.png). Needs python3-vtk9 (and
python3-h5py for HDF5 output) and a display: under a headless shell, run it
through xvfb-run (scripts/run.sh does).
"""
import argparse
import os
import sys
import xml.etree.ElementTree as ET

import vtk


def last_output(pvd, step):
    """The .pvtu of the chosen step (last if None) and its time."""
    root = ET.parse(pvd).getroot()
    sets = root.find("Collection").findall("DataSet")
    if not sets:
        sys.exit(f"error: {pvd} lists no output step")
    chosen = sets[-1] if step is None else sets[step]
    return os.path.join(os.path.dirname(pvd), chosen.get("file")), float(
        chosen.get("timestep"))


def body_part(source, body, inside):
    """Cells of one body (point array 'body' == id) or of all the others."""
    threshold = vtk.vtkThreshold()
    threshold.SetInputConnection(source.GetOutputPort())
    threshold.SetInputArrayToProcess(
        0, 0, 0, vtk.vtkDataObject.FIELD_ASSOCIATION_POINTS, "body")
    threshold.SetLowerThreshold(body - 0.5)
    threshold.SetUpperThreshold(body + 0.5)
    threshold.SetThresholdFunction(vtk.vtkThreshold.THRESHOLD_BETWEEN)
    threshold.SetInvert(not inside)
    threshold.SetAllScalars(True)
    surface = vtk.vtkDataSetSurfaceFilter()
    surface.SetInputConnection(threshold.GetOutputPort())
    return surface


def render(reader, field, args, time, out):
    data = reader.GetOutput()
    if data.GetPointData().GetArray(field) is None:
        names = [data.GetPointData().GetArrayName(i)
                 for i in range(data.GetPointData().GetNumberOfArrays())]
        sys.exit(f"error: no field '{field}' in the output; it has: "
                 + ", ".join(names))
    warp = vtk.vtkWarpVector()
    warp.SetInputConnection(reader.GetOutputPort())
    warp.SetInputArrayToProcess(
        0, 0, 0, vtk.vtkDataObject.FIELD_ASSOCIATION_POINTS, "displacement")
    warp.SetScaleFactor(args.warp)

    renderer = vtk.vtkRenderer()
    renderer.SetBackground(1, 1, 1)
    coloured = body_part(warp, args.body, True)
    coloured.Update()
    value_range = coloured.GetOutput().GetPointData().GetArray(field).GetRange()
    lut = vtk.vtkLookupTable()
    lut.SetHueRange(0.667, 0.0)
    lut.Build()
    mapper = vtk.vtkPolyDataMapper()
    mapper.SetInputConnection(coloured.GetOutputPort())
    mapper.SetScalarModeToUsePointFieldData()
    mapper.SelectColorArray(field)
    mapper.SetScalarRange(value_range[0],
                          max(value_range[1], value_range[0] + 1e-12))
    mapper.SetLookupTable(lut)
    actor = vtk.vtkActor()
    actor.SetMapper(mapper)
    actor.GetProperty().EdgeVisibilityOn()
    actor.GetProperty().SetEdgeColor(0.45, 0.45, 0.45)
    actor.GetProperty().SetLineWidth(0.5)
    renderer.AddActor(actor)

    others = body_part(warp, args.body, False)
    others.Update()
    if others.GetOutput().GetNumberOfCells() > 0:
        grey = vtk.vtkPolyDataMapper()
        grey.SetInputConnection(others.GetOutputPort())
        grey.ScalarVisibilityOff()
        other_actor = vtk.vtkActor()
        other_actor.SetMapper(grey)
        other_actor.GetProperty().SetColor(0.85, 0.85, 0.85)
        other_actor.GetProperty().SetOpacity(0.6)
        renderer.AddActor(other_actor)

    bar = vtk.vtkScalarBarActor()
    bar.SetLookupTable(lut)
    bar.SetTitle(field)
    bar.SetNumberOfLabels(5)
    bar.SetLabelFormat("%.3g")
    bar.UnconstrainedFontSizeOn()
    for text in (bar.GetTitleTextProperty(), bar.GetLabelTextProperty()):
        text.SetColor(0, 0, 0)
        text.ItalicOff()
        text.BoldOff()
        text.SetFontSize(18)
    bar.SetWidth(0.08)
    bar.SetHeight(0.6)
    bar.SetPosition(0.9, 0.2)
    renderer.AddActor2D(bar)

    title = vtk.vtkTextActor()
    title.SetInput(f"{field} at t = {time:g}, displacements x {args.warp:g}")
    title.GetTextProperty().SetColor(0, 0, 0)
    title.GetTextProperty().SetFontSize(18)
    title.SetPosition(10, 10)
    renderer.AddActor2D(title)

    camera = renderer.GetActiveCamera()
    bounds = data.GetBounds()
    if bounds[4] == bounds[5]:
        # A plane-strain run (Dimension = 2): the x-y plane seen from above.
        camera.SetViewUp(0, 1, 0)
        camera.SetPosition(0, 0, 1)
    else:
        camera.SetViewUp(0, 0, 1)
        camera.SetPosition(-1, -1.6, 1.1)
    camera.SetFocalPoint(0, 0, 0)
    renderer.ResetCamera()
    camera.Zoom(1.3 if bounds[4] != bounds[5] else 1.0)

    window = vtk.vtkRenderWindow()
    window.SetOffScreenRendering(1)
    window.AddRenderer(renderer)
    window.SetSize(1200, 800)
    window.Render()
    image = vtk.vtkWindowToImageFilter()
    image.SetInput(window)
    image.Update()
    writer = vtk.vtkPNGWriter()
    writer.SetFileName(out)
    writer.SetInputConnection(image.GetOutputPort())
    writer.Write()
    print(f"-- wrote {out} ({field} from {value_range[0]:.3g} "
          f"to {value_range[1]:.3g})")


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("results")
    parser.add_argument("fields", nargs="*", default=["s", "alpha"])
    parser.add_argument("--body", type=int, default=0)
    parser.add_argument("--warp", type=float, default=1.0)
    parser.add_argument("--step", type=int, default=None)
    parser.add_argument("--out", default=None)
    args = parser.parse_args()
    series = args.results
    if os.path.isdir(series):
        for name in ("solution.pvd", "solution.xdmf"):
            if os.path.isfile(os.path.join(series, name)):
                series = os.path.join(series, name)
                break
    if not os.path.isfile(series):
        sys.exit(f"error: no solution.pvd or solution.xdmf in {args.results} "
                 "(is Output/Interval > 0?)")
    if series.endswith(".xdmf"):
        sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
        import xdmf_grid
        grid, time = xdmf_grid.read(series, args.step)
        reader = xdmf_grid.Source(grid)
    else:
        pvtu, time = last_output(series, args.step)
        reader = vtk.vtkXMLPUnstructuredGridReader()
        reader.SetFileName(pvtu)
        reader.Update()
    for field in args.fields:
        render(reader, field, args, time,
               (args.out + field + ".png") if args.out else
               os.path.join(os.path.dirname(series), field + ".png"))


if __name__ == "__main__":
    main()
