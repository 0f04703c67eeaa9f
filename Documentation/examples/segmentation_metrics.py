# How far Stroke Cut's segments are from a reference segmentation read from a .seg file (the
# Princeton Segmentation Benchmark's format: one segment id per face), in pvpython or pvbatch:
#   PV_PLUGIN_PATH=build/lib/paraview-5.11/plugins/Kerf pvpython Documentation/examples/segmentation_metrics.py
# The reference, Data/camel-neck-plane.seg, cuts the camel's head and neck off at the plane of the
# neck stroke (Data/PROVENANCE.md); the metrics compare the stroke's cut with it.
import os
import sys

from paraview import servermanager, simple

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from cut_from_stroke import DATA, neck_stroke  # noqa: E402

METRICS = ("CutDiscrepancy", "HammingDistance", "MissingRate", "FalseAlarmRate", "RandIndexError",
           "GlobalConsistencyError", "LocalConsistencyError")


def metrics_pipeline():
    """Stroke Cut on the camel, the reference .seg as the cell array Reference, and Segmentation
    Metrics between them."""
    reference = simple.SegmentationReader(Input=neck_stroke(), ArrayName="Reference",
                                          FileName=os.path.join(DATA, "camel-neck-plane.seg"))
    return simple.SegmentationMetrics(Input=reference, EvaluatedSegmentation=["CELLS", "Segment"],
                                      ReferenceSegmentation=["CELLS", "Reference"])


def segmentation_metrics():
    """Returns each metric of Segmentation Metrics' one-row table."""
    metrics = metrics_pipeline()
    metrics.UpdatePipeline()
    table = servermanager.Fetch(metrics)
    return {name: float(table.GetColumnByName(name).GetValue(0)) for name in METRICS}


if __name__ == "__main__":
    for key, value in segmentation_metrics().items():
        print("%-24s %.6f" % (key, value))
