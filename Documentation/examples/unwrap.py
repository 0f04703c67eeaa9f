# Unwrap the camel along the showcase's cut, in pvpython or pvbatch:
#   PV_PLUGIN_PATH=build/lib/paraview-5.11/plugins/Kerf pvpython Documentation/examples/unwrap.py [OUT.png]
# Stroke Cut around the neck -> Curve Export (the cut becomes mesh edges, the two charts it
# bounds) -> Chart Parameterization (texture coordinates, packed into the unit square; seams
# added from the tips of the legs and other protrusions to the neck, where the map was worst). Prints
# the charts and their distortion; with OUT.png, saves the camel textured with
# Data/checkerboard.png beside its UV layout.
import os
import sys

from paraview import servermanager, simple
from vtkmodules.util.numpy_support import vtk_to_numpy

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import cut_from_stroke  # noqa: E402

CHECKERBOARD = os.path.join(cut_from_stroke.DATA, "checkerboard.png")


def unwrap_pipeline():
    """Stroke Cut, Curve Export along its cut, Chart Parameterization; returns the last."""
    cut = cut_from_stroke.neck_stroke()
    export = simple.CurveExport(Input=cut.Input, Curves=simple.OutputPort(cut, 1))
    return simple.ChartParameterization(Input=export, Margin=0.02)


def show(atlas, surface_view):
    """The surface with the checkerboard texture in `surface_view`; the UV layout coloured by
    stretch in a second view beside it, in the same layout. Returns the layout."""
    layout = simple.GetLayout(surface_view)
    layout_view = simple.CreateView("RenderView")
    simple.AssignViewToLayout(layout_view, layout, 0)
    textured = simple.Show(simple.OutputPort(atlas, 0), surface_view)
    textured.ColorArrayName = ["POINTS", ""]
    textured.Texture = simple.CreateTexture(CHECKERBOARD)
    surface_view.CameraPosition = [1.2, 0.6, 2.2]
    surface_view.CameraFocalPoint = [0.0, 0.0, 0.0]
    simple.ResetCamera(surface_view)
    flat = simple.Show(simple.OutputPort(atlas, 1), layout_view)
    simple.ColorBy(flat, ("CELLS", "Stretch"))
    flat.RescaleTransferFunctionToDataRange(False, True)
    flat.SetScalarBarVisibility(layout_view, True)
    layout_view.InteractionMode = "2D"
    layout_view.CameraPosition = [0.5, 0.5, 3.0]
    layout_view.CameraFocalPoint = [0.5, 0.5, 0.0]
    layout_view.CameraViewUp = [0.0, 1.0, 0.0]
    simple.ResetCamera(layout_view)
    return layout


def unwrap(picture=None):
    """Returns the number of charts, the surface's size after the cut, the distortion figures
    and the texture coordinates' range."""
    atlas = unwrap_pipeline()
    atlas.UpdatePipeline()
    if picture:
        surface_view = simple.CreateView("RenderView")
        simple.AssignViewToLayout(surface_view, simple.CreateLayout("unwrap"), 0)
        simple.SaveScreenshot(picture, show(atlas, surface_view), ImageResolution=[1200, 600])
    surface = servermanager.Fetch(atlas)
    field = surface.GetFieldData()
    uv = vtk_to_numpy(surface.GetPointData().GetTCoords())
    return {"charts": int(field.GetArray("ChartCount").GetValue(0)),
            "points": surface.GetNumberOfPoints(), "triangles": surface.GetNumberOfCells(),
            "seams": vtk_to_numpy(field.GetArray("ChartSeams")).tolist(),
            "mean_stretch": field.GetArray("MeanStretch").GetValue(0),
            "l2_stretch": field.GetArray("L2Stretch").GetValue(0),
            "mean_shear": field.GetArray("MeanShear").GetValue(0),
            "flipped": int(field.GetArray("FlippedFaces").GetValue(0)),
            "overlapping_chart_pairs": int(field.GetArray("OverlappingChartPairs").GetValue(0)),
            "uv_range": (float(uv.min()), float(uv.max()))}

if __name__ == "__main__":
    result = unwrap(sys.argv[1] if len(sys.argv) > 1 else None)
    print("charts:", result["charts"], "| seams per chart:", result["seams"], "| points:", result["points"],
          "| triangles:", result["triangles"])
    print("mean stretch:", round(result["mean_stretch"], 3), "| L2 stretch:", round(result["l2_stretch"], 3),
          "| mean shear:", round(result["mean_shear"], 3),
          "| flipped triangles:", result["flipped"], "| overlapping chart pairs:", result["overlapping_chart_pairs"])
