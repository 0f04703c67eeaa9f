# The best-scored isoline of a harmonic field (ROI Scissor's score) on the camel, in pvpython:
#   PV_PLUGIN_PATH=build/lib/paraview-5.11/plugins/Kerf pvpython Documentation/examples/best_isoline.py
# The field comes from the stroke around the neck; Isoline Cut in Best score mode samples 50
# values and keeps the isoline whose score (shortness and concavity) is best.
import os
import sys

from paraview import simple

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from cut_from_stroke import neck_stroke  # noqa: E402


def best_isoline_pipeline(field):
    """Isoline Cut in Best score mode with 50 candidates on `field`'s HarmonicField."""
    return simple.IsolineCut(Input=field, Mode=1, NumberOfCandidates=50)


def best_isoline():
    """Returns the chosen iso-value, its score, its length, its pieces and the candidates' count."""
    field = neck_stroke()
    field.UpdatePipeline()
    isoline = best_isoline_pipeline(field)
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
