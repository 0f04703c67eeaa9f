# kerf.vtkGeodesicDistance, kerf.vtkGeodesicSeam, kerf.vtkGeodesicDisc and kerf.vtkROIScissor from Python: great-circle distances, a seam's length, a cap's area, a hoof's region, errors.
import math
import os
import unittest

import kerf
import numpy
from TestGeodesicPolyline import run, sphere
from vtkmodules.util.numpy_support import vtk_to_numpy
from vtkmodules.vtkCommonCore import vtkPoints
from vtkmodules.vtkCommonDataModel import vtkCellArray, vtkPolyData
from vtkmodules.vtkFiltersCore import vtkAppendPolyData
from vtkmodules.vtkFiltersGeneral import vtkTransformPolyDataFilter
from vtkmodules.vtkCommonTransforms import vtkTransform

DATA = os.path.join(os.environ["KERF_SOURCE_DIR"], "Data")


def polyline(points, closed=False):
    """A vtkPolyData holding one polyline through `points` (its first point repeated if closed)."""
    result = vtkPolyData()
    result.SetPoints(vtkPoints())
    result.GetPoints().SetDataTypeToDouble()
    lines = vtkCellArray()
    lines.InsertNextCell(len(points) + (1 if closed else 0))
    for point in points:
        lines.InsertCellPoint(result.GetPoints().InsertNextPoint(point))
    if closed:
        lines.InsertCellPoint(0)
    result.SetLines(lines)
    return result


def assert_refused(test, algorithm):
    """The algorithm fails with exactly one error; returns it."""
    status, errors = run(algorithm)
    test.assertEqual(status, 0)
    test.assertEqual(len(errors), 1)
    return errors[0]


class GeodesicDistanceTest(unittest.TestCase):
    @classmethod
    def setUpClass(cls):
        cls.surface = sphere()

    def distance(self, **settings):
        distance = kerf.vtkGeodesicDistance()
        distance.SetInputData(0, self.surface)
        for name, value in settings.items():
            getattr(distance, "Set" + name)(value)
        return distance

    def test_heat_distance_matches_great_circles(self):
        distance = self.distance(SourcePoint=(0.0, 0.0, 1.0))
        self.assertEqual(run(distance), (1, []))
        output = distance.GetOutput()
        field = output.GetPointData().GetScalars()
        self.assertEqual(field.GetName(), "GeodesicDistance")
        values = vtk_to_numpy(field)
        points = vtk_to_numpy(output.GetPoints().GetData())
        exact = numpy.arccos(numpy.clip(points[:, 2] / numpy.linalg.norm(points, axis=1), -1.0, 1.0))
        # Outside the source's neighbourhood (two latitude rings of 0.9 degrees).
        away = exact > 2.0 * math.pi / 200.0
        relative = abs(values[away] - exact[away]) / exact[away]
        self.assertLess(relative.mean(), 0.01)
        self.assertLess(relative.max(), 0.03)
        self.assertLess(abs(values[~away]).max(), 0.04)
        # The input keeps its arrays and points.
        self.assertIsNone(self.surface.GetPointData().GetArray("GeodesicDistance"))

    def test_a_second_component_is_unreached(self):
        moved = vtkTransformPolyDataFilter()
        moved.SetInputData(sphere(20))
        transform = vtkTransform()
        transform.Translate(5.0, 0.0, 0.0)
        moved.SetTransform(transform)
        both = vtkAppendPolyData()
        both.AddInputData(sphere(20))
        both.AddInputConnection(moved.GetOutputPort())
        both.Update()
        distance = kerf.vtkGeodesicDistance()
        distance.SetInputData(0, both.GetOutput())
        distance.SetSourcePoint(0.0, 0.0, 1.0)
        self.assertEqual(run(distance), (1, []))
        values = vtk_to_numpy(distance.GetOutput().GetPointData().GetArray("GeodesicDistance"))
        half = len(values) // 2
        self.assertTrue(numpy.isfinite(values[:half]).all())
        self.assertTrue(numpy.isinf(values[half:]).all())
        self.assertAlmostEqual(values[:half].max(), math.pi, delta=0.05 * math.pi)

    def test_bad_input_is_refused(self):
        far = polyline([(0.0, 0.0, 3.0)])
        distance = self.distance()
        distance.SetInputData(1, far)
        self.assertIn("farther", assert_refused(self, distance))
        assert_refused(self, self.distance(SourcePoint=(float("nan"), 0.0, 0.0)))


class GeodesicSeamTest(unittest.TestCase):
    @classmethod
    def setUpClass(cls):
        cls.surface = sphere()
        cls.equator = polyline([(math.cos(a), math.sin(a), 0.0)
                                for a in numpy.linspace(0.0, 2.0 * math.pi, 400, endpoint=False)], closed=True)

    def seam(self, target, gamma=0.0):
        seam = kerf.vtkGeodesicSeam()
        seam.SetInputData(0, self.surface)
        seam.SetInputData(1, self.equator)
        seam.SetGamma(gamma)
        seam.SetTargetPoint(target)
        return seam

    def test_a_seam_from_the_equator_is_a_meridian(self):
        target = (0.6, 0.0, 0.8)
        seam = self.seam(target)
        self.assertEqual(run(seam), (1, []))
        curve = seam.GetOutput(1)
        self.assertEqual(curve.GetNumberOfLines(), 1)
        points = vtk_to_numpy(curve.GetPoints().GetData())
        # From the line (the equator) to the target, along the meridian y = 0.
        self.assertLess(abs(points[0, 2]), 0.01)
        self.assertLess(numpy.linalg.norm(points[-1] - target), 0.01)
        self.assertLess(abs(points[:, 1]).max(), 0.02)
        # The streamline, Euler steps across the triangles, is about 1% longer than the arc.
        length = curve.GetCellData().GetArray("Length").GetValue(0)
        self.assertAlmostEqual(length, math.asin(0.8), delta=0.02 * math.asin(0.8))
        # The field at the target's nearest vertex is the arc's length.
        surface = seam.GetOutput(0)
        field = vtk_to_numpy(surface.GetPointData().GetArray("SeamDistance"))
        nearest = numpy.linalg.norm(vtk_to_numpy(surface.GetPoints().GetData()) - target, axis=1).argmin()
        self.assertAlmostEqual(field[nearest], math.asin(0.8), delta=0.01 * math.asin(0.8))
        self.assertEqual(seam.GetOutput(0).GetFieldData().GetAbstractArray("SeamWork").GetValue(0), "field")
        # A new target reuses the field.
        seam.SetTargetPoint(0.0, -0.8, -0.6)
        self.assertEqual(run(seam), (1, []))
        self.assertEqual(seam.GetOutput(0).GetFieldData().GetAbstractArray("SeamWork").GetValue(0), "regrowth")
        length = seam.GetOutput(1).GetCellData().GetArray("Length").GetValue(0)
        self.assertAlmostEqual(length, math.asin(0.6), delta=0.02 * math.asin(0.6))

    def test_a_line_far_off_the_surface_is_refused(self):
        seam = kerf.vtkGeodesicSeam()
        seam.SetInputData(0, self.surface)
        seam.SetInputData(1, polyline([(0.0, 0.0, 3.0), (0.0, 0.5, 3.0)]))
        seam.SetTargetPoint(0.0, 0.0, 1.0)
        assert_refused(self, seam)


class GeodesicDiscTest(unittest.TestCase):
    @classmethod
    def setUpClass(cls):
        cls.surface = sphere()

    def disc(self, radius, click=(0.0, 0.0, 1.0)):
        disc = kerf.vtkGeodesicDisc()
        disc.SetInputData(0, self.surface)
        disc.SetClickPoint(*click)
        disc.SetAbsoluteRadius(radius)
        return disc

    def test_a_disc_on_the_sphere_is_its_cap(self):
        """Radius 1.2 around the north pole: the cap z > cos 1.2, of area 2 pi (1 - cos 1.2)."""
        disc = self.disc(1.2)
        self.assertEqual(run(disc), (1, []))
        output = disc.GetOutput()
        self.assertEqual(output.GetPointData().GetScalars().GetName(), "GeodesicDisc")
        inside = vtk_to_numpy(output.GetPointData().GetArray("GeodesicDisc"))
        z = vtk_to_numpy(output.GetPoints().GetData())[:, 2]
        away = numpy.abs(numpy.arccos(numpy.clip(z, -1.0, 1.0)) - 1.2) > 0.01
        self.assertTrue(numpy.array_equal(inside[away], (z[away] > math.cos(1.2)).astype(inside.dtype)))
        fields = output.GetFieldData()
        area = fields.GetArray("RegionArea").GetValue(0)
        self.assertAlmostEqual(area / (2.0 * math.pi * (1.0 - math.cos(1.2))), 1.0, delta=0.01)
        self.assertAlmostEqual(fields.GetArray("RegionAreaFraction").GetValue(0), (1.0 - math.cos(1.2)) / 2.0,
                               delta=0.005)
        distance = vtk_to_numpy(output.GetPointData().GetArray("ClickDistance"))
        self.assertLess(numpy.abs(distance - numpy.arccos(numpy.clip(z, -1.0, 1.0))).max(), 0.03)

    def test_a_radius_larger_than_the_sphere_is_refused(self):
        self.assertIn("whole component", assert_refused(self, self.disc(4.0)))


class ROIScissorTest(unittest.TestCase):
    @classmethod
    def setUpClass(cls):
        reader = kerf.vtkKerfOFFReader()
        reader.SetFileName(os.path.join(DATA, "camel.off"))
        reader.Update()
        cls.camel = reader.GetOutput()
        cls.points = vtk_to_numpy(cls.camel.GetPoints().GetData())

    def scissor(self):
        scissor = kerf.vtkROIScissor()
        scissor.SetInputData(0, self.camel)
        scissor.SetClickPoint(*map(float, self.points[self.points[:, 1].argmin()]))  # a front hoof
        scissor.SetRadius(0.2)
        return scissor

    def test_a_click_on_a_hoof_selects_the_hoof(self):
        scissor = self.scissor()
        self.assertEqual(run(scissor), (1, []))
        region = vtk_to_numpy(scissor.GetOutput(0).GetCellData().GetArray("RoiRegion"))
        self.assertEqual(len(region), self.camel.GetNumberOfCells())
        self.assertTrue(0 < region.sum() < 0.1 * len(region))
        boundary = scissor.GetOutput(1)
        self.assertEqual(boundary.GetNumberOfLines(), 1)
        self.assertEqual(boundary.GetCellData().GetArray("Closed").GetValue(0), 1)
        self.assertEqual(boundary.GetCellData().GetArray("SelfCrossings").GetValue(0), 0)
        # Every region face lies below the boundary's highest point: the hoof, not the body.
        centers = self.points[vtk_to_numpy(self.camel.GetPolys().GetConnectivityArray()).reshape(-1, 3)].mean(axis=1)
        top = vtk_to_numpy(boundary.GetPoints().GetData())[:, 1].max()
        self.assertLessEqual(centers[region == 1][:, 1].max(), top + 1e-9)
        # The same input gives the same region, bit for bit.
        again = self.scissor()
        self.assertEqual(run(again), (1, []))
        self.assertTrue(numpy.array_equal(
            vtk_to_numpy(again.GetOutput(0).GetCellData().GetArray("RoiRegion")), region))

    def test_a_click_off_the_surface_is_refused(self):
        scissor = self.scissor()
        click = vtkPolyData()
        click.SetPoints(vtkPoints())
        click.GetPoints().InsertNextPoint(0.0, 100.0, 0.0)
        scissor.SetInputData(1, click)
        assert_refused(self, scissor)


if __name__ == "__main__":
    unittest.main()
