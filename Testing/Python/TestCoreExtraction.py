# kerf.vtkCoreExtractionSegmentation from Python: the camel's parts, the same labels for the camel
# scaled by 2 (a pose- and scale-invariant method), a bent copy of a limb-like shape, and errors.
import math
import os
import unittest

import kerf
from TestBadInput import update_and_capture_errors
from vtkmodules.util.numpy_support import vtk_to_numpy
from vtkmodules.vtkCommonDataModel import vtkPolyData
from vtkmodules.vtkFiltersGeneral import vtkTransformFilter
from vtkmodules.vtkCommonTransforms import vtkTransform

CAMEL = os.path.join(os.environ["KERF_SOURCE_DIR"], "Data", "camel.off")


def segment(surface, **parameters):
    """The filter's status, output labels and field data on `surface` (a vtkPolyData)."""
    segmentation = kerf.vtkCoreExtractionSegmentation()
    for name, value in parameters.items():
        getattr(segmentation, "Set" + name)(value)
    segmentation.SetInputData(surface)
    status = segmentation.GetExecutive().Update()
    output = segmentation.GetOutput()
    labels = output.GetCellData().GetArray("Segment")
    return status, (vtk_to_numpy(labels).tolist() if labels else []), output


def camel():
    reader = kerf.vtkKerfMeshFileReader()
    reader.SetFileName(CAMEL)
    reader.Update()
    return reader.GetOutput()


class CoreExtractionTest(unittest.TestCase):
    @classmethod
    def setUpClass(cls):
        cls.camel = camel()
        cls.status, cls.labels, cls.output = segment(cls.camel)

    def test_the_camel_has_parts_each_connected(self):
        self.assertEqual(self.status, 1)
        self.assertEqual(len(self.labels), 19536)
        count = int(self.output.GetFieldData().GetArray("SegmentCount").GetValue(0))
        self.assertEqual(sorted(set(self.labels)), list(range(count)))
        # The head and neck, four legs and the tail at least come off the body.
        self.assertGreaterEqual(count, 6)
        features = self.output.GetFieldData().GetArray("FeatureFaces")
        self.assertEqual(features.GetNumberOfTuples(),
                         int(self.output.GetFieldData().GetArray("FeaturePoints").GetValue(0)))
        core = vtk_to_numpy(self.output.GetCellData().GetArray("Core"))
        self.assertEqual(len(core), 19536)
        self.assertTrue(0 < int(core.sum()) < 19536)
        # The input is untouched: no array added to it.
        self.assertIsNone(self.camel.GetCellData().GetArray("Segment"))

    def test_scaled_by_two_gives_the_same_labels(self):
        transform = vtkTransform()
        transform.Scale(2.0, 2.0, 2.0)
        scaled = vtkTransformFilter()
        scaled.SetTransform(transform)
        scaled.SetInputData(self.camel)
        scaled.Update()
        status, labels, _ = segment(scaled.GetOutput())
        self.assertEqual(status, 1)
        self.assertEqual(labels, self.labels)

    def test_a_larger_feature_radius_gives_no_more_parts(self):
        counts = []
        for radius in (0.2, 0.5):
            status, labels, _ = segment(self.camel, FeatureRadius=radius)
            self.assertEqual(status, 1)
            counts.append(len(set(labels)))
        self.assertLessEqual(counts[1], counts[0])

    def test_bad_parameters_and_input_fail_cleanly(self):
        for name, value, phrase in (("FeatureRadius", math.nan, "FeatureRadius must be a number"),
                                    ("CoarseSize", 3, "coarse size must be at least 10"),
                                    ("HullTolerance", 1.0, "hull tolerance must lie in [0, 1)"),
                                    ("ExtensionFactor", 0.0, "extension factor must lie in (0, 1)"),
                                    ("BandWidth", -1.0, "boundary band")):
            with self.subTest(parameter=name):
                segmentation = kerf.vtkCoreExtractionSegmentation()
                getattr(segmentation, "Set" + name)(value)
                segmentation.SetInputData(self.camel)
                status, messages = update_and_capture_errors(segmentation)
                self.assertEqual(status, 0)
                self.assertIn(phrase, messages[0])
                self.assertEqual(segmentation.GetOutput().GetNumberOfCells(), 0)
        segmentation = kerf.vtkCoreExtractionSegmentation()
        segmentation.SetInputData(vtkPolyData())
        status, messages = update_and_capture_errors(segmentation)
        self.assertEqual(status, 0)
        self.assertIn("no triangles", messages[0])

if __name__ == "__main__":
    unittest.main()
