# kerf.vtkSurfaceDescriptors from Python: the package imports, and a sphere gets curvature 1/R.
import unittest

import kerf
from vtkmodules.util.numpy_support import vtk_to_numpy
from vtkmodules.vtkCommonExecutionModel import vtkPolyDataAlgorithm
from vtkmodules.vtkFiltersSources import vtkSphereSource

RADIUS = 2.5
RESOLUTION = 128

# Default output array names (vtkSurfaceDescriptors.h) and their component counts.
OUTPUT_ARRAYS = {
    "Normals": 3,
    "MaximumCurvature": 1,
    "MinimumCurvature": 1,
    "MaximumCurvatureDirection": 3,
    "MinimumCurvatureDirection": 3,
    "MeanCurvature": 1,
    "GaussianCurvature": 1,
    "Concave": 1,
    "NormalConeAngle": 1,
}


class SurfaceDescriptorsTest(unittest.TestCase):
    @classmethod
    def setUpClass(cls):
        sphere = vtkSphereSource()
        sphere.SetRadius(RADIUS)
        sphere.SetThetaResolution(RESOLUTION)
        sphere.SetPhiResolution(RESOLUTION)
        descriptors = kerf.vtkSurfaceDescriptors()
        descriptors.SetInputConnection(sphere.GetOutputPort())
        cls.update_status = descriptors.GetExecutive().Update()
        cls.output = descriptors.GetOutput()

    def test_import(self):
        descriptors = kerf.vtkSurfaceDescriptors()
        self.assertIsInstance(descriptors, vtkPolyDataAlgorithm)
        self.assertEqual(descriptors.GetMeanCurvatureArrayName(), "MeanCurvature")

    def test_update_succeeds(self):
        self.assertEqual(self.update_status, 1)
        self.assertEqual(self.output.GetNumberOfPoints(), RESOLUTION * (RESOLUTION - 2) + 2)

    def test_every_array_has_one_tuple_per_point(self):
        point_data = self.output.GetPointData()
        for name, components in OUTPUT_ARRAYS.items():
            with self.subTest(array=name):
                array = point_data.GetArray(name)
                self.assertIsNotNone(array)
                self.assertEqual(array.GetNumberOfTuples(), self.output.GetNumberOfPoints())
                self.assertEqual(array.GetNumberOfComponents(), components)

    def test_sphere_curvature_is_one_over_radius(self):
        point_data = self.output.GetPointData()
        mean = vtk_to_numpy(point_data.GetArray("MeanCurvature"))
        gaussian = vtk_to_numpy(point_data.GetArray("GaussianCurvature"))
        self.assertLess(abs(mean * RADIUS - 1).mean(), 0.01)
        self.assertLess(abs(gaussian * RADIUS**2 - 1).mean(), 0.01)


if __name__ == "__main__":
    unittest.main()
