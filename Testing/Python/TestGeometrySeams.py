# kerf.vtkGeometrySeams from Python: a cylinder painted handle / modeling / fixed gets its field, rings and contours.
import math
import unittest

import kerf
import numpy
from vtkmodules.util.numpy_support import numpy_to_vtk, numpy_to_vtkIdTypeArray, vtk_to_numpy
from vtkmodules.vtkCommonDataModel import vtkCellArray, vtkPolyData
from vtkmodules.vtkCommonCore import vtkPoints

AROUND, RINGS, HEIGHT = 48, 49, 4.0


def painted_cylinder():
    """Open cylinder of radius 1 around z; Region 2 (handle) for z <= 1, 0 (fixed) for z >= 3, else 1."""
    j, i = numpy.meshgrid(numpy.arange(RINGS), numpy.arange(AROUND), indexing="ij")
    u = 2 * math.pi * i.ravel() / AROUND
    z = HEIGHT * j.ravel() / (RINGS - 1)
    xyz = numpy.column_stack([numpy.cos(u), numpy.sin(u), z])
    triangles = []
    for row in range(RINGS - 1):
        for col in range(AROUND):
            a, b = row * AROUND + col, row * AROUND + (col + 1) % AROUND
            c, d = b + AROUND, a + AROUND
            triangles += [(a, b, c), (a, c, d)]
    points = vtkPoints()
    points.SetData(numpy_to_vtk(xyz, deep=True))
    cells = vtkCellArray()
    connectivity = numpy.array(triangles, dtype=numpy.int64)
    offsets = numpy.arange(0, 3 * len(triangles) + 1, 3, dtype=numpy.int64)
    cells.SetData(numpy_to_vtkIdTypeArray(offsets, deep=True), numpy_to_vtkIdTypeArray(connectivity.ravel(), deep=True))
    surface = vtkPolyData()
    surface.SetPoints(points)
    surface.SetPolys(cells)
    region = numpy.where(z <= 1.0, 2.0, numpy.where(z >= 3.0, 0.0, 1.0))
    array = numpy_to_vtk(region, deep=True)
    array.SetName("Region")
    surface.GetPointData().AddArray(array)
    return surface, z, region


class GeometrySeamsTest(unittest.TestCase):
    @classmethod
    def setUpClass(cls):
        cls.surface, cls.z, cls.region = painted_cylinder()
        seams = kerf.vtkGeometrySeams()
        seams.SetInputData(cls.surface)
        seams.SetNumberOfRings(5)
        seams.SetNumberOfSectors(4)
        cls.status = seams.GetExecutive().Update()
        cls.output = seams.GetOutput()
        cls.contours = seams.GetContours()
        cls.seams = seams

    def test_defaults(self):
        seams = kerf.vtkGeometrySeams()
        self.assertEqual(seams.GetNumberOfRings(), 15)
        self.assertEqual(seams.GetNumberOfIsoContours(), 10)
        self.assertEqual((seams.GetAlpha(), seams.GetBeta(), seams.GetGamma()), (1.0, 0.25, 1.0))

    def test_field_is_linear_in_z(self):
        self.assertEqual(self.status, 1)
        field = vtk_to_numpy(self.output.GetPointData().GetArray("HarmonicField"))
        inside = self.region == 1.0
        self.assertLess(numpy.abs(field[inside] - (self.z[inside] - 1.0) / 2.0).max(), 1e-9)
        self.assertTrue((field[self.region == 2.0] == 0.0).all())
        self.assertTrue((field[self.region == 0.0] == 1.0).all())

    def test_rings_and_sectors(self):
        ring = vtk_to_numpy(self.output.GetCellData().GetArray("RingSeam"))
        self.assertEqual(sorted(set(ring.tolist())), [-1, 0, 1, 2, 3, 4])
        for k in range(5):
            self.assertGreaterEqual((ring == k).sum(), 2 * AROUND)  # a strip all the way round
        sector = vtk_to_numpy(self.output.GetPointData().GetArray("Sector"))
        self.assertEqual(sorted(set(sector[self.region == 1.0].tolist())), [0, 1, 2, 3])
        self.assertTrue((sector[self.region != 1.0] == -1).all())
        self.assertEqual(self.output.GetFieldData().GetArray("RingCount").GetValue(0), 5)

    def test_contours(self):
        kind = vtk_to_numpy(self.contours.GetCellData().GetArray("Kind"))
        self.assertEqual(int((kind == 0).sum()), 11)
        self.assertEqual(int((kind == 1).sum()), 4)

    def test_input_untouched(self):
        self.assertEqual(self.surface.GetPointData().GetNumberOfArrays(), 1)
        self.assertEqual(self.surface.GetCellData().GetNumberOfArrays(), 0)


if __name__ == "__main__":
    unittest.main()
