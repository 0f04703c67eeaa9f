# kerf.vtkRegionGrowing -> kerf.vtkSnakeRefinement from Python: the armadillo's head cut from its body by the bundled strokes, as kerf.vtkEasyMeshCut does in one step.
import os
import unittest

import kerf
import numpy
from vtkmodules.util.numpy_support import vtk_to_numpy
from vtkmodules.vtkIOLegacy import vtkPolyDataReader

DATA = os.path.join(os.environ["KERF_SOURCE_DIR"], "Data")


def segments(algorithm, port=0):
    return vtk_to_numpy(algorithm.GetOutputDataObject(port).GetCellData().GetArray("Segment"))


class EasyMeshCuttingTest(unittest.TestCase):
    @classmethod
    def setUpClass(cls):
        cls.armadillo = kerf.vtkOFFReader()
        cls.armadillo.SetFileName(os.path.join(DATA, "armadillo.off"))
        cls.strokes = vtkPolyDataReader()
        cls.strokes.SetFileName(os.path.join(DATA, "armadillo-head-strokes.vtk"))

    def test_two_steps_equal_one(self):
        growing = kerf.vtkRegionGrowing()
        growing.SetInputConnection(0, self.armadillo.GetOutputPort())
        growing.SetInputConnection(1, self.strokes.GetOutputPort())
        snake = kerf.vtkSnakeRefinement()
        snake.SetInputConnection(growing.GetOutputPort())
        snake.Update()
        cut = kerf.vtkEasyMeshCut()
        cut.SetInputConnection(0, self.armadillo.GetOutputPort())
        cut.SetInputConnection(1, self.strokes.GetOutputPort())
        cut.Update()
        # The head with its ears: 5,622 faces grown, 5,559 after the snake (as the example).
        self.assertEqual(int((segments(growing) == 1).sum()), 5622)
        refined = segments(snake)
        self.assertEqual(int((refined == 1).sum()), 5559)
        numpy.testing.assert_array_equal(refined, segments(cut))
        boundary = snake.GetBoundary()
        self.assertEqual(boundary.GetNumberOfCells(), 1)
        self.assertEqual(boundary.GetCellData().GetArray("Closed").GetValue(0), 1)
        self.assertAlmostEqual(boundary.GetCellData().GetArray("Length").GetValue(0),
                               cut.GetBoundary().GetCellData().GetArray("Length").GetValue(0), places=12)
        # Every vertex is reached (one component); the distance is 0 on the strokes' vertices only.
        grown = growing.GetOutput()
        self.assertEqual(grown.GetFieldData().GetArray("UnreachableVertices").GetValue(0), 0)
        labels = vtk_to_numpy(grown.GetPointData().GetArray("Segment"))
        self.assertEqual(sorted(set(labels.tolist())), [0, 1])
        distance = vtk_to_numpy(grown.GetPointData().GetArray("IsophoticDistance"))
        self.assertTrue((distance >= 0).all())
        self.assertLess(int((distance == 0).sum()), 200)

    def test_cut_band_zero_keeps_the_fronts(self):
        """CutBand 0 turns cut placement off: the head as the fronts meet, ragged (four chains)."""
        growing = kerf.vtkRegionGrowing()
        growing.SetInputConnection(0, self.armadillo.GetOutputPort())
        growing.SetInputConnection(1, self.strokes.GetOutputPort())
        self.assertEqual(growing.GetCutBand(), 0.3)
        growing.SetCutBand(0.0)
        growing.Update()
        self.assertEqual(int((segments(growing) == 1).sum()), 6322)
        self.assertEqual(growing.GetBoundary().GetNumberOfCells(), 4)
        growing.SetCutBand(0.3)
        growing.Update()
        self.assertEqual(int((segments(growing) == 1).sum()), 5622)
        self.assertEqual(growing.GetBoundary().GetNumberOfCells(), 1)

    def test_snake_refines_another_array(self):
        """Snake Refinement refines whichever cell array it is given and replaces it."""
        growing = kerf.vtkRegionGrowing()
        growing.SetInputConnection(0, self.armadillo.GetOutputPort())
        growing.SetInputConnection(1, self.strokes.GetOutputPort())
        growing.SetSegmentArrayName("Part")
        snake = kerf.vtkSnakeRefinement()
        snake.SetInputConnection(growing.GetOutputPort())
        snake.SetInputArrayToProcess(0, 0, 0, 1, "Part")  # 1: cells
        snake.Update()
        part = vtk_to_numpy(snake.GetOutput().GetCellData().GetArray("Part"))
        self.assertEqual(int((part == 1).sum()), 5559)
        self.assertIsNone(snake.GetOutput().GetCellData().GetArray("Segment"))


if __name__ == "__main__":
    unittest.main()
