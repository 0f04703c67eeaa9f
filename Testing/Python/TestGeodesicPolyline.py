# kerf.vtkGeodesicPolyline (Geodesic Polyline) from Python: a sphere's great circles, arc lengths, both metrics, errors.
import math
import unittest

import kerf
import numpy
from TestBadInput import update_and_capture_errors
from vtkmodules.util.numpy_support import vtk_to_numpy
from vtkmodules.vtkCommonCore import reference, vtkPoints
from vtkmodules.vtkCommonDataModel import vtkPolyData
from vtkmodules.vtkCommonTransforms import vtkTransform
from vtkmodules.vtkFiltersCore import vtkAppendPolyData
from vtkmodules.vtkFiltersGeneral import vtkTransformPolyDataFilter
from vtkmodules.vtkFiltersSources import vtkSphereSource

START = (0.6, 0.0, 0.8)
END = (0.0, 0.6, -0.8)


def sphere(resolution=200):
    """A unit UV sphere of 200 x 200 cells (79,600 triangles)."""
    source = vtkSphereSource()
    source.SetRadius(1.0)
    source.SetThetaResolution(resolution)
    source.SetPhiResolution(resolution)
    source.Update()
    return source.GetOutput()


def points(*coordinates):
    result = vtkPolyData()
    result.SetPoints(vtkPoints())
    result.GetPoints().SetDataTypeToDouble()
    for point in coordinates:
        result.GetPoints().InsertNextPoint(point)
    return result


def run(path):
    """Updates `path`; returns the executive's status and its first error, captured."""
    status, messages = update_and_capture_errors(path)
    return status, messages[:1]


def great_circle(a, b):
    a, b = numpy.asarray(a), numpy.asarray(b)
    return math.acos(numpy.clip(a.dot(b) / numpy.linalg.norm(a) / numpy.linalg.norm(b), -1.0, 1.0))


class GeodesicPolylineTest(unittest.TestCase):
    @classmethod
    def setUpClass(cls):
        cls.surface = sphere()

    def path(self, *coordinates, **settings):
        path = kerf.vtkGeodesicPolyline()
        path.SetInputData(0, self.surface)
        path.SetInputData(1, points(*coordinates))
        for name, value in settings.items():
            getattr(path, "Set" + name)(value)
        return path

    def test_defaults(self):
        path = kerf.vtkGeodesicPolyline()
        self.assertEqual(path.GetMetric(), kerf.vtkGeodesicPolyline.ISOTROPIC)
        self.assertEqual((path.GetGamma(), path.GetDepth(), path.GetClosedLoop()), (1.0, 3, False))
        self.assertEqual(path.GetNumberOfPathPoints(), 0)

    def test_great_circle_and_arc_length(self):
        path = self.path(START, END)
        self.assertEqual(run(path), (1, []))
        output = path.GetOutput()
        xyz = vtk_to_numpy(output.GetPoints().GetData())
        total = output.GetFieldData().GetArray("TotalLength").GetValue(0)
        exact = great_circle(xyz[0], xyz[-1])
        self.assertAlmostEqual(total, exact, delta=0.01 * exact)
        # Isotropic: the arc length is the Euclidean length along the polyline.
        steps = numpy.linalg.norm(numpy.diff(xyz, axis=0), axis=1)
        arc = vtk_to_numpy(output.GetPointData().GetArray("ArcLength"))
        numpy.testing.assert_allclose(arc, numpy.concatenate([[0.0], numpy.cumsum(steps)]), rtol=0, atol=1e-12)
        # The path keeps to the plane of its great circle (within the facets' sag).
        normal = numpy.cross(xyz[0], xyz[-1])
        normal /= numpy.linalg.norm(normal)
        self.assertLess(numpy.abs(xyz @ normal).max(), 0.01)
        # Every point lies on the input cell its Face array names.
        faces = vtk_to_numpy(output.GetPointData().GetArray("Face"))
        for point, face in zip(xyz, faces):
            squared_distance, sub_id = reference(0.0), reference(0)
            self.surface.GetCell(int(face)).EvaluatePosition(
                point, [0.0] * 3, sub_id, [0.0] * 3, squared_distance, [0.0] * 3)
            self.assertLess(float(squared_distance), 1e-18)

    def test_gamma_zero_matches_isotropic(self):
        lengths = []
        for settings in ({}, {"Metric": kerf.vtkGeodesicPolyline.ANISOTROPIC, "Gamma": 0.0}):
            path = self.path(START, END, **settings)
            self.assertEqual(run(path), (1, []))
            lengths.append(path.GetOutput().GetFieldData().GetArray("TotalLength").GetValue(0))
        self.assertAlmostEqual(lengths[1], lengths[0], delta=0.01 * lengths[0])

    def test_open_path_through_three_points(self):
        middle = (0.8, 0.6, 0.0)
        path = self.path(START, middle, END)
        self.assertEqual(run(path), (1, []))
        output = path.GetOutput()
        waypoints = vtk_to_numpy(output.GetPointData().GetArray("PathPoint"))
        self.assertEqual(waypoints[waypoints >= 0].tolist(), [0, 1, 2])
        xyz = vtk_to_numpy(output.GetPoints().GetData())
        legs = great_circle(xyz[0], xyz[waypoints == 1][0]) + great_circle(xyz[waypoints == 1][0], xyz[-1])
        total = output.GetFieldData().GetArray("TotalLength").GetValue(0)
        self.assertAlmostEqual(total, legs, delta=0.01 * legs)

    def test_errors(self):
        status, messages = run(self.path(START, (0.0, 0.0, 3.0)))
        self.assertEqual(status, 0)
        self.assertIn("path point 1 lies off the surface", messages[0])
        status, messages = run(self.path(START, END, ClosedLoop=True))
        self.assertIn("needs at least 3 points, got 2", messages[0])
        # Two spheres: no path joins them.
        moved = vtkTransformPolyDataFilter()
        transform = vtkTransform()
        transform.Translate(5.0, 0.0, 0.0)
        moved.SetTransform(transform)
        moved.SetInputData(self.surface)
        both = vtkAppendPolyData()
        both.AddInputData(self.surface)
        both.AddInputConnection(moved.GetOutputPort())
        both.Update()
        path = kerf.vtkGeodesicPolyline()
        path.SetInputData(0, both.GetOutput())
        path.SetInputData(1, points(START, (5.6, 0.0, 0.8)))
        status, messages = run(path)
        self.assertEqual(status, 0)
        self.assertIn("path point 1 lies on another connected component", messages[0])
        self.assertEqual(path.GetOutput().GetNumberOfPoints(), 0)


if __name__ == "__main__":
    unittest.main()
