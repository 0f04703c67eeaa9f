# Bad input fails the update from Python with an error naming the problem, captured so that
# nothing prints "ERROR:".
import math
import os
import unittest

import kerf
from vtkmodules.util.misc import calldata_type
from vtkmodules.util.vtkConstants import VTK_STRING
from vtkmodules.vtkCommonCore import vtkCommand, vtkPoints
from vtkmodules.vtkCommonDataModel import vtkCellArray, vtkPolyData
from vtkmodules.vtkFiltersSources import vtkSphereSource


def update_and_capture_errors(algorithm):
    """Updates `algorithm`; returns the executive's status and the error messages it raised."""
    messages = []

    @calldata_type(VTK_STRING)
    def collect(caller, event, message):
        # Drop VTK's "ERROR: In file, line n / class (address): " preamble.
        messages.append(message.split("): ", 1)[-1].strip())

    executive = algorithm.GetExecutive()
    tags = [(algorithm, algorithm.AddObserver(vtkCommand.ErrorEvent, collect)),
            (executive, executive.AddObserver(vtkCommand.ErrorEvent, collect))]
    status = executive.Update()
    for observed, tag in tags:
        observed.RemoveObserver(tag)
    return status, messages


def triangle(points):
    """A vtkPolyData holding one triangle through `points`."""
    mesh = vtkPolyData()
    mesh.SetPoints(vtkPoints())
    for point in points:
        mesh.GetPoints().InsertNextPoint(point)
    mesh.SetPolys(vtkCellArray())
    mesh.GetPolys().InsertNextCell(3, (0, 1, 2))
    return mesh


class BadInputTest(unittest.TestCase):
    def assert_refused(self, algorithm, phrase):
        status, messages = update_and_capture_errors(algorithm)
        self.assertEqual(status, 0)
        self.assertTrue(messages, "no error was reported")
        self.assertIn(phrase, messages[0])

    def test_valid_triangle_is_accepted(self):
        descriptors = kerf.vtkSurfaceDescriptors()
        descriptors.SetInputData(triangle([(0, 0, 0), (1, 0, 0), (0, 1, 0)]))
        self.assertEqual(update_and_capture_errors(descriptors), (1, []))

    def test_empty_mesh(self):
        descriptors = kerf.vtkSurfaceDescriptors()
        descriptors.SetInputData(vtkPolyData())
        self.assert_refused(descriptors, "no triangles")
        self.assertEqual(descriptors.GetOutput().GetNumberOfPoints(), 0)

    def test_nan_point(self):
        descriptors = kerf.vtkSurfaceDescriptors()
        descriptors.SetInputData(triangle([(0, 0, 0), (1, math.nan, 0), (0, 1, 0)]))
        self.assert_refused(descriptors, "NaN or infinite coordinates")

    def test_missing_off_file(self):
        reader = kerf.vtkOFFReader()
        reader.SetFileName(os.path.join(os.environ["KERF_TEST_OUTPUT"], "does-not-exist.off"))
        self.assert_refused(reader, "does-not-exist.off")

    def test_segmentation_with_wrong_label_count(self):
        path = os.path.join(os.environ["KERF_TEST_OUTPUT"], "PythonTooFewLabels.seg")
        with open(path, "w") as labels:
            labels.write("0\n1\n")
        sphere = vtkSphereSource()
        reader = kerf.vtkSegmentationReader()
        reader.SetInputConnection(sphere.GetOutputPort())
        reader.SetFileName(path)
        self.assert_refused(reader, "has 2 labels but the mesh has")


if __name__ == "__main__":
    unittest.main()
