# The best-scored isoline of a harmonic field (ROI Scissor's score) on the camel, in pvpython:
#   PV_PLUGIN_PATH=build/lib/paraview-5.11/plugins/Kerf pvpython Documentation/examples/best_isoline.py
# The field comes from the stroke around the neck; Isoline Cut in Best score mode samples 50
# values and keeps the isoline whose score (shortness and concavity) is best.
import os

from paraview import servermanager, simple
from vtkmodules.util.numpy_support import vtk_to_numpy

DATA = os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "Data")


def best_isoline():
    """Returns the chosen iso-value, its score, its length, its pieces and the candidates' count."""
    camel = simple.OpenDataFile(os.path.join(DATA, "camel.off"))
    # The stroke's points, as a user would place them in the panel (P on the surface).
    stroke = servermanager.Fetch(
        simple.LegacyVTKReader(FileNames=[os.path.join(DATA, "camel-neck-stroke.vtk")]))
    points = vtk_to_numpy(stroke.GetPoints().GetData()).ravel().tolist()
    field = simple.CutFromStroke(Input=camel, StrokePoints=points)
    field.UpdatePipeline()
    isoline = simple.IsolineCut(Input=field, Mode=1, NumberOfCandidates=50)
    isoline.UpdatePipeline()
    candidates = isoline.GetDataInformation(2).GetNumberOfRows()
    return {"iso_value": isoline.CellData["IsoValue"].GetRange()[0],
            "score": isoline.CellData["Score"].GetRange()[0],
            "length": isoline.CellData["Length"].GetRange()[1],
            "pieces": isoline.GetDataInformation().GetNumberOfCells(),
            "candidates": candidates}


if __name__ == "__main__":
    for key, value in best_isoline().items():
        print(key + ":", value)
