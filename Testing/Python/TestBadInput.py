# Bad input fails the update from Python with an error naming the problem, captured so that
# nothing prints "ERROR:".
import math
import os
import unittest

import kerf
from vtkmodules.util.misc import calldata_type
from vtkmodules.util.vtkConstants import VTK_STRING
from vtkmodules.vtkCommonCore import vtkCommand, vtkDoubleArray, vtkPoints
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
        reader = kerf.vtkKerfOFFReader()
        reader.SetFileName(os.path.join(os.environ["KERF_TEST_OUTPUT"], "does-not-exist.off"))
        self.assert_refused(reader, "does-not-exist.off")

    def test_segmentation_with_wrong_label_count(self):
        path = os.path.join(os.environ["KERF_TEST_OUTPUT"], "PythonTooFewLabels.seg")
        with open(path, "w") as labels:
            labels.write("0\n1\n")
        sphere = vtkSphereSource()
        reader = kerf.vtkKerfSegmentationReader()
        reader.SetInputConnection(sphere.GetOutputPort())
        reader.SetFileName(path)
        self.assert_refused(reader, "has 2 labels but the mesh has")


def octahedron(scale=1.0):
    """A closed octahedron (6 points, 8 triangles) scaled by `scale`."""
    mesh = vtkPolyData()
    mesh.SetPoints(vtkPoints())
    mesh.GetPoints().SetDataTypeToDouble()
    for point in [(1, 0, 0), (-1, 0, 0), (0, 1, 0), (0, -1, 0), (0, 0, 1), (0, 0, -1)]:
        mesh.GetPoints().InsertNextPoint([scale * c for c in point])
    mesh.SetPolys(vtkCellArray())
    for face in [(0, 2, 4), (2, 1, 4), (1, 3, 4), (3, 0, 4), (2, 0, 5), (1, 2, 5), (3, 1, 5), (0, 3, 5)]:
        mesh.GetPolys().InsertNextCell(3, face)
    return mesh


def point_set(points, name=None, values=()):
    """Points (no cells) with an optional one-component point array."""
    data = vtkPolyData()
    data.SetPoints(vtkPoints())
    for point in points:
        data.GetPoints().InsertNextPoint(point)
    if name is not None:
        array = vtkDoubleArray()
        array.SetName(name)
        for value in values:
            array.InsertNextValue(value)
        data.GetPointData().AddArray(array)
    return data


def polyline(points, ids):
    """A polyline through `ids` of `points` (ids may be out of range on purpose)."""
    line = point_set(points)
    line.SetLines(vtkCellArray())
    line.GetLines().InsertNextCell(len(ids), ids)
    return line


class BadConstraintsTest(unittest.TestCase):
    """Arrays, strokes and parameters that do not fit the surface are refused, not read past their ends."""

    assert_refused = BadInputTest.assert_refused

    def field_with_hard_values(self, values):
        surface = octahedron()
        surface.GetPointData().AddArray(point_set([], "Hard", values).GetPointData().GetArray("Hard"))
        field = kerf.vtkHarmonicField()
        field.SetInputData(surface)
        field.SetInputArrayToProcess(0, 0, 0, 0, "Hard")
        field.UseHardValuesOn()
        return field

    def test_hard_values_of_the_wrong_length(self):
        self.assert_refused(self.field_with_hard_values([0.0] + [math.nan] * 4 + [1.0] * 100),
                            "has 105 values for 6 points")

    def test_hard_values_switched_off(self):
        field = self.field_with_hard_values([0.0] + [math.nan] * 4 + [1.0])
        self.assertEqual(update_and_capture_errors(field), (1, []))
        field.UseHardValuesOff()
        self.assert_refused(field, "no constraint")

    def test_hard_values_too_large(self):
        self.assert_refused(self.field_with_hard_values([-1e308] + [math.nan] * 4 + [1e308]), "overflows")

    def test_constraint_values_of_the_wrong_length(self):
        field = kerf.vtkHarmonicField()
        field.SetInputData(octahedron())
        field.SetInputData(1, point_set([(1, 0, 0), (-1, 0, 0), (0, 0, 1)], "ConstraintValue", [1.0]))
        self.assert_refused(field, "has 1 values for 3 points")

    def test_many_soft_constraints_are_solved(self):
        # More constraints than unknowns: factored with the Laplacian term, in well under a second.
        points = [(1, 0, 0), (-1, 0, 0)] * 2000
        field = kerf.vtkHarmonicField()
        field.SetInputData(octahedron())
        field.SetInputData(1, point_set(points, "ConstraintValue", [1.0, -1.0] * 2000))
        self.assertEqual(update_and_capture_errors(field), (1, []))
        values = [field.GetOutput().GetPointData().GetArray("HarmonicField").GetValue(i) for i in range(6)]
        # By symmetry the field is odd in x: f(-x) = -f(x), 0 on the four vertices of x = 0; the
        # weighted constraints pull the two tips close to +-1.
        self.assertAlmostEqual(values[0], -values[1], places=12)
        for value in values[2:]:
            self.assertAlmostEqual(value, 0.0, places=12)
        self.assertGreater(values[0], 0.99)
        self.assertLess(values[0], 1.0)

    def test_stroke_line_with_a_point_id_out_of_range(self):
        stroke = kerf.vtkStrokeConstraints()
        stroke.SetInputData(octahedron())
        stroke.SetInputData(1, polyline([(1, 0, 0), (0.7, 0.7, 0)], (0, 1, 50000000)))
        self.assert_refused(stroke, "uses point 50000000, but the stroke input has 2 points")

    def test_stroke_line_without_points(self):
        stroke = kerf.vtkStrokeConstraints()
        stroke.SetInputData(octahedron())
        stroke.SetInputData(1, polyline([], (0, 1)))
        self.assert_refused(stroke, "uses point 0, but the stroke input has 0 points")

    def test_stroke_with_nan_iso_value(self):
        stroke = kerf.vtkStrokeConstraints()
        stroke.SetInputData(octahedron())
        stroke.SetStrokePoint(0, 1, 0, 0)
        stroke.SetStrokePoint(1, 0.7, 0.7, 0)
        stroke.SetIsoValue(math.nan)
        self.assert_refused(stroke, "must be finite")

    def test_stroke_point_far_beyond_the_mesh(self):
        stroke = kerf.vtkStrokeConstraints()
        stroke.SetInputData(octahedron())
        stroke.SetInputData(1, polyline([(0, 1e308, 0), (0.7, 0.7, 0)], (0, 1)))
        self.assert_refused(stroke, "stroke 0 has a point with NaN, infinite or huge coordinates")

    def test_absurd_stroke_point_counts_are_refused_without_allocating(self):
        stroke = kerf.vtkStrokeConstraints()
        for call in (lambda: stroke.SetStrokePoint(2 ** 31 - 1, 0, 0, 0),
                     lambda: stroke.SetNumberOfStrokePoints(2 ** 31 - 1)):
            errors = []

            @calldata_type(VTK_STRING)
            def collect(caller, event, message):
                errors.append(message)
            tag = stroke.AddObserver(vtkCommand.ErrorEvent, collect)
            call()
            stroke.RemoveObserver(tag)
            self.assertEqual(stroke.GetNumberOfStrokePoints(), 0)
            self.assertTrue(errors and "at most 10000000 points" in errors[0], errors)

    def test_nan_parameters_are_refused(self):
        for setter in ("SetConcaveBeta", "SetConcavityQuantile", "SetSoftConstraintWeight"):
            with self.subTest(setter=setter):
                field = kerf.vtkHarmonicField()
                field.SetInputData(octahedron())
                field.SetInputData(1, point_set([(1, 0, 0), (-1, 0, 0)], "ConstraintValue", [1.0, -1.0]))
                field.SetWeightingToConcavityAware()
                getattr(field, setter)(math.nan)
                self.assert_refused(field, "must be a number, not NaN")

    def test_needle_triangles_have_finite_curvature(self):
        # A quad with one vertex 1e8 away: a needle and a sliver. Never NaN output.
        mesh = vtkPolyData()
        mesh.SetPoints(vtkPoints())
        for point in ((0, 0, 0), (1, 0, 0), (1, 1e8, 0), (0, 1, 0)):
            mesh.GetPoints().InsertNextPoint(point)
        mesh.SetPolys(vtkCellArray())
        mesh.GetPolys().InsertNextCell(3, (0, 1, 2))
        mesh.GetPolys().InsertNextCell(3, (0, 2, 3))
        descriptors = kerf.vtkSurfaceDescriptors()
        descriptors.SetInputData(mesh)
        self.assertEqual(update_and_capture_errors(descriptors), (1, []))
        for name in ("MaximumCurvature", "MinimumCurvature", "MeanCurvature", "GaussianCurvature"):
            array = descriptors.GetOutput().GetPointData().GetArray(name)
            self.assertEqual([array.GetValue(i) for i in range(4)], [0.0] * 4, name)

    def test_cut_near_a_nan_stroke(self):
        surface = octahedron()
        surface.GetPointData().AddArray(point_set([], "HarmonicField", [1, -1, 0.5, -0.5, 0.2, -0.2])
                                        .GetPointData().GetArray("HarmonicField"))
        cut = kerf.vtkIsolineCut()
        cut.SetInputData(surface)
        cut.SetInputData(1, point_set([(math.nan, 0, 0)]))
        cut.SetModeToNearStroke()
        self.assert_refused(cut, "stroke point 0 has a NaN")

    def test_huge_and_tiny_meshes(self):
        for scale, phrase in ((1e300, "beyond +-1e50"), (1e-300, "below 1e-50")):
            with self.subTest(scale=scale):
                descriptors = kerf.vtkSurfaceDescriptors()
                descriptors.SetInputData(octahedron(scale))
                self.assert_refused(descriptors, phrase)

    def test_points_edited_in_place(self):
        # vtkPoints::SetPoint does not change the points' modification time: the cached surface
        # must still notice.
        surface = octahedron()
        constraints = point_set([(1, 0, 0), (-1, 0, 0)], "ConstraintValue", [1.0, -1.0])
        field = kerf.vtkHarmonicField()
        field.SetInputData(surface)
        field.SetInputData(1, constraints)
        self.assertEqual(update_and_capture_errors(field), (1, []))
        for i in range(surface.GetNumberOfPoints()):
            x, y, z = surface.GetPoint(i)
            surface.GetPoints().SetPoint(i, x, y, 2 * z)
        surface.Modified()
        self.assertEqual(update_and_capture_errors(field), (1, []))
        self.assertEqual(field.GetOutput().GetFieldData().GetAbstractArray("SolverWork").GetValue(0), "factorization")
        self.assertEqual(field.GetOutput().GetPoint(4), (0.0, 0.0, 2.0))


if __name__ == "__main__":
    unittest.main()
