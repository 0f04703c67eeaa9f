# Kerf's readers and writers from Python: OFF meshes and Princeton benchmark .seg round trips.
import os
import unittest

import kerf
import numpy
from vtkmodules.util.numpy_support import numpy_to_vtk, vtk_to_numpy
from vtkmodules.vtkCommonDataModel import vtkPolyData
from vtkmodules.vtkFiltersSources import vtkSphereSource

CAMEL = os.path.join(os.environ["KERF_SOURCE_DIR"], "Data", "camel.off")
OUTPUT = os.environ["KERF_TEST_OUTPUT"]


class MeshIOTest(unittest.TestCase):
    def assert_camel(self, reader):
        reader.SetFileName(CAMEL)
        self.assertEqual(reader.GetExecutive().Update(), 1)
        mesh = reader.GetOutput()
        self.assertEqual(mesh.GetNumberOfPoints(), 9770)
        self.assertEqual(mesh.GetNumberOfCells(), 19536)
        self.assertEqual(mesh.GetNumberOfPolys(), 19536)

    def test_off_reader(self):
        self.assert_camel(kerf.vtkKerfOFFReader())

    def test_mesh_file_reader(self):
        self.assert_camel(kerf.vtkKerfMeshFileReader())

    def test_segmentation_round_trip(self):
        sphere = vtkSphereSource()
        sphere.Update()
        mesh = vtkPolyData()
        mesh.ShallowCopy(sphere.GetOutput())
        cells = mesh.GetNumberOfCells()
        labels = numpy.arange(cells, dtype=numpy.int32) % 5
        labels[-1] = 1234567
        array = numpy_to_vtk(labels, deep=True)
        array.SetName("Segment")
        mesh.GetCellData().AddArray(array)
        path = os.path.join(OUTPUT, "PythonSegmentationRoundTrip.seg")

        writer = kerf.vtkKerfSegmentationWriter()
        writer.SetInputData(mesh)
        writer.SetFileName(path)
        self.assertEqual(writer.Write(), 1)
        with open(path) as written:
            self.assertEqual(len(written.read().split()), cells)

        reader = kerf.vtkKerfSegmentationReader()
        reader.SetInputData(sphere.GetOutput())
        reader.SetFileName(path)
        reader.SetArrayName("ReadBack")
        self.assertEqual(reader.GetExecutive().Update(), 1)
        read_back = reader.GetOutput().GetCellData().GetArray("ReadBack")
        self.assertIsNotNone(read_back)
        self.assertEqual(read_back.GetNumberOfTuples(), cells)
        self.assertEqual(vtk_to_numpy(read_back).tolist(), labels.tolist())


if __name__ == "__main__":
    unittest.main()
