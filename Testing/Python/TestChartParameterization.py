# kerf.vtkChartParameterization from Python: a plane cut into two charts unrolls exactly into the unit square, with LSCM and with LinABF.
import unittest

import numpy
import kerf
from vtkmodules.util.numpy_support import numpy_to_vtk, vtk_to_numpy
from vtkmodules.vtkCommonDataModel import vtkDataObject, vtkPolyData
from vtkmodules.vtkFiltersCore import vtkTriangleFilter
from vtkmodules.vtkFiltersSources import vtkPlaneSource

MARGIN = 0.05


def labelled_plane():
    plane = vtkPlaneSource()
    plane.SetOrigin(0.0, 0.0, 0.0)
    plane.SetPoint1(3.0, 0.0, 1.0)
    plane.SetPoint2(0.0, 2.0, 0.0)
    plane.SetResolution(30, 20)
    triangles = vtkTriangleFilter()
    triangles.SetInputConnection(plane.GetOutputPort())
    triangles.Update()
    surface = vtkPolyData()
    surface.DeepCopy(triangles.GetOutput())
    centres_x = []
    for cell in range(surface.GetNumberOfCells()):
        ids = surface.GetCell(cell).GetPointIds()
        centres_x.append(sum(surface.GetPoint(ids.GetId(k))[0] for k in range(3)) / 3.0)
    labels = numpy_to_vtk(numpy.array([0 if x < 1.5 else 7 for x in centres_x], dtype=numpy.int32), deep=True)
    labels.SetName("Segment")
    surface.GetCellData().AddArray(labels)
    return surface


class ChartParameterizationTest(unittest.TestCase):
    @classmethod
    def setUpClass(cls):
        cls.input = labelled_plane()
        atlas = kerf.vtkChartParameterization()
        atlas.SetInputData(cls.input)
        atlas.SetInputArrayToProcess(0, 0, 0, vtkDataObject.FIELD_ASSOCIATION_CELLS, "Segment")
        atlas.SetMargin(MARGIN)
        cls.status = atlas.GetExecutive().Update()
        cls.surface = atlas.GetOutput(0)
        cls.layout = atlas.GetOutput(1)

    def test_texture_coordinates(self):
        self.assertEqual(self.status, 1)
        uv = vtk_to_numpy(self.surface.GetPointData().GetTCoords())
        self.assertEqual(self.surface.GetPointData().GetTCoords().GetName(), "UV")
        self.assertGreaterEqual(uv.min(), MARGIN - 1e-12)
        self.assertLessEqual(uv.max(), 1.0 - MARGIN + 1e-12)
        # The 21 points on the border x = 1.5 are repeated, one copy per chart.
        self.assertEqual(self.surface.GetNumberOfPoints(), self.input.GetNumberOfPoints() + 21)

    def test_a_plane_is_not_distorted(self):
        for name in ("Stretch", "Shear"):
            values = vtk_to_numpy(self.surface.GetCellData().GetArray(name))
            self.assertLess(numpy.abs(values - 1.0).max(), 1e-9, name)
        self.assertEqual(vtk_to_numpy(self.surface.GetCellData().GetArray("Flipped")).sum(), 0)
        self.assertEqual(self.surface.GetFieldData().GetArray("ChartCount").GetValue(0), 2)
        self.assertEqual(self.surface.GetFieldData().GetArray("OverlappingChartPairs").GetValue(0), 0)

    def test_layout_is_flat(self):
        points = vtk_to_numpy(self.layout.GetPoints().GetData())
        self.assertEqual(numpy.abs(points[:, 2]).max(), 0.0)
        uv = vtk_to_numpy(self.surface.GetPointData().GetTCoords())
        self.assertTrue(numpy.array_equal(points[:, :2], uv))

    def test_linear_angle_based_flattening(self):
        """LinABF (Method 1) unrolls the plane exactly too, into the same square."""
        atlas = kerf.vtkChartParameterization()
        self.assertEqual(atlas.GetMethod(), kerf.vtkChartParameterization.LSCM)
        atlas.SetMethodToLinABF()
        self.assertEqual(atlas.GetMethod(), kerf.vtkChartParameterization.LINABF)
        atlas.SetInputData(self.input)
        atlas.SetInputArrayToProcess(0, 0, 0, vtkDataObject.FIELD_ASSOCIATION_CELLS, "Segment")
        atlas.SetMargin(MARGIN)
        self.assertEqual(atlas.GetExecutive().Update(), 1)
        surface = atlas.GetOutput(0)
        for name in ("Stretch", "Shear"):
            values = vtk_to_numpy(surface.GetCellData().GetArray(name))
            self.assertLess(numpy.abs(values - 1.0).max(), 1e-9, name)
        self.assertEqual(vtk_to_numpy(surface.GetCellData().GetArray("Flipped")).sum(), 0)
        uv = vtk_to_numpy(surface.GetPointData().GetTCoords())
        self.assertGreaterEqual(uv.min(), MARGIN - 1e-12)
        self.assertLessEqual(uv.max(), 1.0 - MARGIN + 1e-12)
        # A plane's charts are the same rectangles with either method: the same layout.
        lscm = vtk_to_numpy(self.surface.GetPointData().GetTCoords())
        self.assertLess(numpy.abs(uv - lscm).max(), 1e-5)

    def test_original_point_ids(self):
        ids = vtk_to_numpy(self.surface.GetPointData().GetArray("OriginalPointId"))
        for point in (0, 100, len(ids) - 1):
            self.assertEqual(self.surface.GetPoint(point), self.input.GetPoint(int(ids[point])))


if __name__ == "__main__":
    unittest.main()
