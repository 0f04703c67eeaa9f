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
        cls.armadillo = kerf.vtkKerfOFFReader()
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
        # The head with its ears: 5,810 faces grown, 5,736 after the snake (as the example).
        self.assertEqual(int((segments(growing) == 1).sum()), 5810)
        refined = segments(snake)
        self.assertEqual(int((refined == 1).sum()), 5736)
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
        self.assertEqual(int((distance == 0).sum()), 96)  # the strokes' vertices
        # The random walks' probabilities: 1 on the strokes, at least 1/2 elsewhere (two labels).
        probability = vtk_to_numpy(grown.GetPointData().GetArray("Probability"))
        self.assertTrue((probability[distance == 0] == 1).all())
        self.assertGreaterEqual(float(probability.min()), 0.5 - 1e-12)

    def test_boundary_placements(self):
        """The three placements on the same strokes: the fronts take the most of the neck, the
        walks and their cut the least, the minimum cut close behind; CutBand 0 keeps the fronts, or the walks' own
        boundary (along the shell's rim: the cut through the walks' band takes the short way
        across the back of the skull instead)."""
        growing = kerf.vtkRegionGrowing()
        growing.SetInputConnection(0, self.armadillo.GetOutputPort())
        growing.SetInputConnection(1, self.strokes.GetOutputPort())
        self.assertEqual(growing.GetBoundaryPlacement(), kerf.vtkRegionGrowing.BOUNDARY_RANDOM_WALKS)
        self.assertEqual(growing.GetCutBand(), 0.3)
        expected = {kerf.vtkRegionGrowing.BOUNDARY_FRONTS: 7606,
                    kerf.vtkRegionGrowing.BOUNDARY_MINIMUM_CUT: 5852,
                    kerf.vtkRegionGrowing.BOUNDARY_RANDOM_WALKS: 5810}
        for placement, faces in expected.items():
            growing.SetBoundaryPlacement(placement)
            growing.Update()
            self.assertEqual(int((segments(growing) == 1).sum()), faces, placement)
            self.assertEqual(growing.GetBoundary().GetNumberOfCells(), 1, placement)
            probability = growing.GetOutput().GetPointData().GetArray("Probability")
            self.assertEqual(probability is not None, placement == kerf.vtkRegionGrowing.BOUNDARY_RANDOM_WALKS)
        growing.SetCutBand(0.0)
        growing.Update()
        self.assertEqual(int((segments(growing) == 1).sum()), 6567)
        growing.SetBoundaryPlacementToMinimumCut()
        growing.Update()
        self.assertEqual(int((segments(growing) == 1).sum()), 7606)
        growing.SetBoundaryPlacement(7)  # clamped to the last placement
        self.assertEqual(growing.GetBoundaryPlacement(), kerf.vtkRegionGrowing.BOUNDARY_RANDOM_WALKS)

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
        self.assertEqual(int((part == 1).sum()), 5736)
        self.assertIsNone(snake.GetOutput().GetCellData().GetArray("Segment"))


if __name__ == "__main__":
    unittest.main()
