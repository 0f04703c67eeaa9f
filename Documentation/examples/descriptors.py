# The camel's curvatures and other surface descriptors, in pvpython or pvbatch:
#   PV_PLUGIN_PATH=build/lib/paraview-5.11/plugins/Kerf pvpython Documentation/examples/descriptors.py [OUT.png]
# Prints the share of concave vertices and the middle 90% of the mean curvature; with OUT.png,
# saves the camel coloured by mean curvature over that middle 90% (a few sharp vertices would
# otherwise stretch the colour map until the rest of the surface shows one colour).
import os
import sys

import numpy
from paraview import servermanager, simple
from vtkmodules.util.numpy_support import vtk_to_numpy

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from cut_from_stroke import DATA  # noqa: E402


def camel_descriptors():
    """The camel and Surface Descriptors with its defaults."""
    camel = simple.OpenDataFile(os.path.join(DATA, "camel.off"))
    return simple.SurfaceDescriptors(Input=camel)


def show(descriptors, view, mean_curvature_range):
    """Shows the descriptors coloured by mean curvature over `mean_curvature_range`."""
    display = simple.Show(descriptors, view)
    simple.ColorBy(display, ("POINTS", "MeanCurvature"))
    simple.GetColorTransferFunction("MeanCurvature").RescaleTransferFunction(*mean_curvature_range)
    display.SetScalarBarVisibility(view, True)
    view.CameraPosition = [1.2, 0.6, 2.2]
    view.CameraFocalPoint = [0.0, 0.0, 0.0]
    simple.ResetCamera(view)


def descriptors(picture=None):
    """Returns the number of points, the share of concave vertices and the 5th and 95th
    percentiles of the mean curvature."""
    result = camel_descriptors()
    result.UpdatePipeline()
    surface = servermanager.Fetch(result)
    mean = vtk_to_numpy(surface.GetPointData().GetArray("MeanCurvature"))
    concave = vtk_to_numpy(surface.GetPointData().GetArray("Concave"))
    middle = tuple(float(value) for value in numpy.percentile(mean, [5.0, 95.0]))
    if picture:
        view = simple.CreateView("RenderView", ViewSize=[600, 600])
        show(result, view, middle)
        simple.SaveScreenshot(picture, view, ImageResolution=[600, 600])
    return {"points": surface.GetNumberOfPoints(), "concave_share": float((concave > 0).mean()),
            "mean_curvature_5_95": middle}


if __name__ == "__main__":
    for key, value in descriptors(sys.argv[1] if len(sys.argv) > 1 else None).items():
        print(key + ":", value)
