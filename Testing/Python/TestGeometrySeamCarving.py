# kerf.vtkGeometrySeamCarving from Python: Geometry Seams then the carving in one pipeline, a vtkTransform moving the handle, splits and their undo.
import unittest

import kerf
import numpy
from vtkmodules.util.numpy_support import vtk_to_numpy
from vtkmodules.vtkCommonTransforms import vtkTransform

from TestGeometrySeams import AROUND, painted_cylinder


class GeometrySeamCarvingTest(unittest.TestCase):
    @classmethod
    def setUpClass(cls):
        cls.surface, cls.z, cls.region = painted_cylinder()  # handle z <= 1, fixed z >= 3
        cls.seams = kerf.vtkGeometrySeams()
        cls.seams.SetInputData(cls.surface)
        cls.seams.SetNumberOfRings(10)
        cls.seams.SetNumberOfSectors(4)

    def carving(self):
        carving = kerf.vtkGeometrySeamCarving()
        carving.SetInputConnection(self.seams.GetOutputPort())
        handle = vtkTransform()
        carving.SetHandleTransform(handle)
        return carving, handle

    def field(self, output, name):
        return output.GetFieldData().GetArray(name).GetValue(0)

    def test_defaults(self):
        carving = kerf.vtkGeometrySeamCarving()
        self.assertEqual(carving.GetStiffnessScale(), 10.0)
        self.assertEqual(carving.GetStiffnessEpsilon(), 0.1)
        self.assertTrue(carving.GetPlastic())
        self.assertEqual(carving.GetSalientThreshold(), 0.5)
        self.assertIsNone(carving.GetHandleTransform())

    def test_stretch_splits_rings_and_the_identity_undoes_them(self):
        carving, handle = self.carving()
        points = self.surface.GetNumberOfPoints()
        for dz in (-0.5, -1.0):  # the modeling region, 2 tall, becomes 3 tall
            handle.Identity()
            handle.Translate(0.0, 0.0, dz)
            self.assertEqual(carving.GetExecutive().Update(), 1)
        output = carving.GetOutput()
        split = self.field(output, "SplitSegments")
        self.assertGreater(split, 0)
        self.assertGreater(output.GetNumberOfPoints(), points)
        origin = vtk_to_numpy(output.GetPointData().GetArray("OriginalPointId"))
        self.assertEqual((origin == -1).sum(), output.GetNumberOfPoints() - points)
        z = vtk_to_numpy(output.GetPoints().GetData())[:, 2]
        self.assertAlmostEqual(z.min(), -1.0, places=12)  # the handle moved down by 1
        self.assertAlmostEqual(z.max(), 4.0, places=12)   # the fixed region stayed
        for dz in (-0.5, 0.0):
            handle.Identity()
            handle.Translate(0.0, 0.0, dz)
            self.assertEqual(carving.GetExecutive().Update(), 1)
        back = carving.GetOutput()
        self.assertEqual(self.field(back, "SplitSegments"), 0)
        self.assertEqual(back.GetNumberOfPoints(), points)
        moved = vtk_to_numpy(back.GetPoints().GetData()) - vtk_to_numpy(self.surface.GetPoints().GetData())
        self.assertLess(numpy.abs(moved).max(), 1e-9)

    def test_plastic_off_keeps_the_triangles(self):
        carving, handle = self.carving()
        carving.PlasticOff()
        handle.Translate(0.0, 0.0, -1.0)
        self.assertEqual(carving.GetExecutive().Update(), 1)
        self.assertEqual(carving.GetOutput().GetNumberOfCells(), self.surface.GetNumberOfCells())
        self.assertEqual(self.field(carving.GetOutput(), "SplitSegments"), 0)

    def test_a_singular_transform_is_refused(self):
        carving, handle = self.carving()
        handle.Scale(1.0, 0.0, 1.0)
        carving.GlobalWarningDisplayOff()
        self.assertEqual(carving.GetExecutive().Update(), 0)
        self.assertEqual(carving.GetOutput().GetNumberOfPoints(), 0)


if __name__ == "__main__":
    unittest.main()
