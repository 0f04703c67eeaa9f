# Cut the armadillo's head from its body with Easy Mesh Cut, in pvpython or pvbatch:
#   PV_PLUGIN_PATH=build/lib/paraview-5.11/plugins/Kerf pvpython Documentation/examples/easy_mesh_cut.py [OUT.png]
# The strokes of Data/armadillo-head-strokes.vtk: label 1 along the face and over the crown,
# label 0 down the chest and down the shell's back. Prints the faces of each part and the
# boundary's length, grown and refined as a snake; with OUT.png, saves a picture of the parts, the
# strokes and the boundary.
import os
import sys

from paraview import servermanager, simple
from vtkmodules.util.numpy_support import vtk_to_numpy

DATA = os.path.normpath(os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "Data"))


def head_cut():
    """The armadillo, its strokes and Easy Mesh Cut (snake refinement on, the default)."""
    armadillo = simple.OpenDataFile(os.path.join(DATA, "armadillo.off"))
    strokes = simple.LegacyVTKReader(FileNames=[os.path.join(DATA, "armadillo-head-strokes.vtk")])
    return simple.EasyMeshCut(Input=armadillo, Strokes=strokes)


def show(cut, view):
    """Shows the parts, the strokes (yellow) and the boundary (black) from above the right shoulder."""
    simple.ColorBy(simple.Show(cut, view), ("CELLS", "Segment"))
    for source, colour in ((simple.OutputPort(cut, 1), [0.1, 0.1, 0.1]), (cut.Strokes, [1.0, 0.85, 0.0])):
        line = simple.Show(source, view)
        line.ColorArrayName = ["POINTS", ""]
        line.AmbientColor = line.DiffuseColor = colour
        line.LineWidth = 4.0
        line.RenderLinesAsTubes = 1
    view.CameraPosition = [-150.0, 160.0, -170.0]
    view.CameraFocalPoint = [0.0, 55.0, 0.0]
    view.CameraViewUp = [0.0, 1.0, 0.0]
    simple.ResetCamera(view)


def measure(cut):
    """The faces of each label, the boundaries' count and total length, and the height (y) range of
    the face centres of label 1 and of the whole surface."""
    cut.UpdatePipeline()
    surface = servermanager.Fetch(cut)
    segments = vtk_to_numpy(surface.GetCellData().GetArray("Segment"))
    points = vtk_to_numpy(surface.GetPoints().GetData())
    corners = vtk_to_numpy(surface.GetPolys().GetConnectivityArray()).reshape(-1, 3)
    heights = points[corners, 1].mean(axis=1)
    boundary = servermanager.Fetch(cut, idx=1)
    lengths = vtk_to_numpy(boundary.GetCellData().GetArray("Length"))
    return {"segment_sizes": [int((segments == label).sum()) for label in sorted(set(segments.tolist()))],
            "boundaries": int(boundary.GetNumberOfCells()), "boundary_length": float(lengths.sum()),
            "label_1_heights": [float(heights[segments == 1].min()), float(heights[segments == 1].max())],
            "heights": [float(heights.min()), float(heights.max())]}


def easy_mesh_cut(picture=None):
    """Returns the refined cut's measures, and the grown one's under "grown"."""
    cut = head_cut()
    cut.Refine = 0
    grown = measure(cut)
    cut.Refine = 1
    result = measure(cut)
    result["grown"] = grown
    if picture:
        view = simple.CreateView("RenderView", ViewSize=[600, 600])
        show(cut, view)
        simple.SaveScreenshot(picture, view, ImageResolution=[600, 600])
    return result


if __name__ == "__main__":
    result = easy_mesh_cut(sys.argv[1] if len(sys.argv) > 1 else None)
    for name, measures in (("grown", result["grown"]), ("refined", result)):
        print("%-8s parts (faces): %s, boundaries: %d, length %.1f" % (
            name, measures["segment_sizes"], measures["boundaries"], measures["boundary_length"]))
