# Cut the camel along a stroke drawn around its neck, in pvpython or pvbatch:
#   PV_PLUGIN_PATH=build/lib/paraview-5.11/plugins/Kerf pvpython Documentation/examples/cut_from_stroke.py [OUT.png]
# Prints the size of each segment; with OUT.png, saves a picture of the segments and the cut.
import os
import sys

from paraview import servermanager, simple
from vtkmodules.util.numpy_support import vtk_to_numpy

DATA = os.path.normpath(os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "Data"))


def neck_stroke():
    """The camel and Stroke Cut with the neck stroke's points, as a user would place them in
    the panel (P on the surface)."""
    camel = simple.OpenDataFile(os.path.join(DATA, "camel.off"))
    stroke = servermanager.Fetch(
        simple.LegacyVTKReader(FileNames=[os.path.join(DATA, "camel-neck-stroke.vtk")]))
    points = vtk_to_numpy(stroke.GetPoints().GetData()).ravel().tolist()
    return simple.StrokeCut(Input=camel, StrokePoints=points)


def show(cut, view, colour_by="Segment"):
    """Shows the segments (or another cell array of the cut's surface) and the cut in `view`."""
    display = simple.Show(cut, view)
    simple.ColorBy(display, ("CELLS", colour_by))
    curve = simple.Show(simple.OutputPort(cut, 1), view)
    curve.ColorArrayName = ["POINTS", ""]
    curve.AmbientColor = curve.DiffuseColor = [0.1, 0.1, 0.1]
    curve.LineWidth = 3.0
    view.CameraPosition = [1.2, 0.6, 2.2]
    view.CameraFocalPoint = [0.0, 0.0, 0.0]
    simple.ResetCamera(view)


def cut_from_stroke(picture=None):
    """Returns the number of faces of each segment, the cut's length and the solver's work."""
    cut = neck_stroke()
    cut.UpdatePipeline()
    surface = servermanager.Fetch(cut)
    segments = vtk_to_numpy(surface.GetCellData().GetArray("Segment"))
    curve = servermanager.Fetch(cut, idx=1)
    length = float(vtk_to_numpy(curve.GetCellData().GetArray("Length")).sum())
    if picture:
        view = simple.CreateView("RenderView", ViewSize=[600, 600])
        show(cut, view)
        simple.SaveScreenshot(picture, view, ImageResolution=[600, 600])
    sizes = [int((segments == label).sum()) for label in sorted(set(segments.tolist()))]
    return {"segment_sizes": sizes, "cut_length": length,
            "solver_work": surface.GetFieldData().GetAbstractArray("SolverWork").GetValue(0)}


if __name__ == "__main__":
    result = cut_from_stroke(sys.argv[1] if len(sys.argv) > 1 else None)
    print("segments (faces):", result["segment_sizes"])
    print("cut length:", round(result["cut_length"], 4))
