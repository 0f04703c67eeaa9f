# The examples of Documentation/examples, run as a user would and checked by their numbers: the
# pvpython scripts, and the ParaView state files loaded from another folder with the Data folder
# given for their files (what the GUI's "Search files under specified directory" does).
import os
import sys
import unittest

from paraview import servermanager, simple
from vtkmodules.util.numpy_support import vtk_to_numpy

EXAMPLES = os.path.join(os.environ["KERF_SOURCE_DIR"], "Documentation", "examples")
sys.path.insert(0, EXAMPLES)
simple.LoadPlugin(os.environ["KERF_PLUGIN"])

import best_isoline  # noqa: E402
import cut_from_stroke  # noqa: E402
import descriptors  # noqa: E402
import easy_mesh_cut  # noqa: E402
import segmentation_metrics  # noqa: E402
import unwrap  # noqa: E402

CAMEL_FACES = 19536


class ExamplesTest(unittest.TestCase):
    def test_cut_from_stroke(self):
        result = cut_from_stroke.cut_from_stroke()
        # The neck stroke splits the camel into the head and neck (5,828 faces) and the body.
        self.assertEqual(result["segment_sizes"], [5828, 13708])
        self.assertEqual(sum(result["segment_sizes"]), CAMEL_FACES)
        # One loop around the neck, about 0.30 long (the neck's girth at the stroke).
        self.assertAlmostEqual(result["cut_length"], 0.2954, delta=0.003)
        self.assertEqual(result["solver_work"], "factorization")

    def test_best_isoline(self):
        result = best_isoline.best_isoline()
        self.assertEqual(result["candidates"], 50)
        # The best-scored isoline is one loop around the neck, a little shorter than the
        # stroke's own cut.
        self.assertEqual(result["pieces"], 1)
        self.assertAlmostEqual(result["length"], 0.284, delta=0.003)


    def test_descriptors(self):
        result = descriptors.descriptors()
        self.assertEqual(result["points"], 9770)
        # About a fifth of the camel's vertices are concave (creases at the legs, neck, humps).
        self.assertAlmostEqual(result["concave_share"], 0.207062, places=5)
        low, high = result["mean_curvature_5_95"]
        self.assertAlmostEqual(low, -37.88, delta=0.01)
        self.assertAlmostEqual(high, 92.78, delta=0.01)

    def test_segmentation_metrics(self):
        result = segmentation_metrics.segmentation_metrics()
        # The stroke's cut and the plane of Data/camel-neck-plane.seg differ by a few faces at the
        # neck: 5,828 and 5,831 faces on the head's side.
        self.assertAlmostEqual(result["RandIndexError"], 0.000307, delta=2e-6)
        self.assertAlmostEqual(result["HammingDistance"], 0.000199, delta=2e-6)
        self.assertAlmostEqual(result["CutDiscrepancy"], 0.00206, delta=2e-5)

    def test_unwrap(self):
        result = unwrap.unwrap()
        # The head and the body, cut apart at the neck; the body gets seams from its legs, tail
        # and humps to the neck, the head from its ears and snout (baselines); no chart overlaps.
        self.assertEqual(result["charts"], 2)
        self.assertEqual(result["seams"], [3, 10])
        self.assertEqual(result["overlapping_chart_pairs"], 0)
        self.assertEqual(result["flipped"], 4)
        self.assertAlmostEqual(result["mean_shear"], 1.0605, delta=0.002)
        self.assertGreaterEqual(result["uv_range"][0], 0.02 - 1e-7)  # single precision
        self.assertLessEqual(result["uv_range"][1], 0.98 + 1e-7)
        # The scissor cut adds 114 triangles along the neck; every seam copies its vertices.
        self.assertEqual(result["triangles"], CAMEL_FACES + 114)
        self.assertGreater(result["points"], 9770 + 114)

    def test_easy_mesh_cut(self):
        result = easy_mesh_cut.easy_mesh_cut()
        # A stroke along the face and over the crown against strokes down the chest and the
        # shell's back: the head with its ears (5,736 of the armadillo's 52,000 faces) meets the
        # body along one closed boundary. Grown (random walks, then the cut through their band,
        # which takes the short way across the back of the skull), the boundary follows edges
        # round the head (154.1 long, one chain); the snake shortens it to 111.3, moving 74 faces
        # to the body.
        self.assertEqual(result["segment_sizes"], [46264, 5736])
        self.assertEqual(result["boundaries"], 1)
        self.assertAlmostEqual(result["boundary_length"], 111.3, delta=0.5)
        grown = result["grown"]
        self.assertEqual(grown["segment_sizes"], [46190, 5810])
        self.assertAlmostEqual(grown["boundary_length"], 154.1, delta=0.5)
        self.assertLess(result["boundary_length"], 0.8 * grown["boundary_length"])
        # Label 1 is the head: it holds the topmost face (an ear) and lies in the top 30% of the
        # armadillo's height (face centres from 0.696 of it up, grown and refined).
        for measures in (result, grown):
            low, high = measures["heights"]
            self.assertEqual(measures["label_1_heights"][1], high)
            self.assertGreater(measures["label_1_heights"][0], low + 0.68 * (high - low))

    def load_state(self, name, mesh="camel.off"):
        """Loads states/<name>.pvsm from the test's own folder, its files found under Data;
        returns its proxies by XML name."""
        before = set(simple.GetSources().values())
        simple.LoadState(os.path.join(EXAMPLES, "states", name + ".pvsm"),
                         data_directory=cut_from_stroke.DATA, restrict_to_data_directory=True)
        loaded = {proxy.GetXMLName(): proxy for proxy in set(simple.GetSources().values()) - before}
        for proxy in loaded.values():
            proxy.UpdatePipeline()
        reader = loaded["KerfOFFReader"]
        self.assertEqual(reader.FileName, os.path.join(cut_from_stroke.DATA, mesh))
        return loaded

    def test_states(self):
        self.assertNotEqual(os.getcwd(), os.environ["KERF_SOURCE_DIR"])
        with self.subTest(state="cut_from_stroke"):
            segments = vtk_to_numpy(servermanager.Fetch(self.load_state("cut_from_stroke")["KerfStrokeCut"])
                                    .GetCellData().GetArray("Segment"))
            self.assertEqual(sorted(int((segments == label).sum()) for label in set(segments.tolist())), [5828, 13708])
        with self.subTest(state="best_isoline"):
            isoline = self.load_state("best_isoline")["KerfIsolineCut"]
            self.assertEqual(isoline.GetDataInformation().GetNumberOfCells(), 1)
            self.assertAlmostEqual(isoline.CellData["Length"].GetRange()[1], 0.284, delta=0.003)
        with self.subTest(state="descriptors"):
            result = servermanager.Fetch(self.load_state("descriptors")["KerfSurfaceDescriptors"])
            concave = vtk_to_numpy(result.GetPointData().GetArray("Concave"))
            self.assertAlmostEqual(float((concave > 0).mean()), 0.207062, places=5)
        with self.subTest(state="segmentation_metrics"):
            table = servermanager.Fetch(self.load_state("segmentation_metrics")["KerfSegmentationMetrics"])
            self.assertAlmostEqual(table.GetColumnByName("RandIndexError").GetValue(0), 0.000307, delta=2e-6)
        with self.subTest(state="easy_mesh_cut"):
            cut = servermanager.Fetch(self.load_state("easy_mesh_cut", "armadillo.off")["KerfEasyMeshCut"])
            segments = vtk_to_numpy(cut.GetCellData().GetArray("Segment"))
            self.assertEqual(int((segments == 1).sum()), 5736)
        with self.subTest(state="unwrap"):
            loaded = self.load_state("unwrap")
            surface = servermanager.Fetch(loaded["KerfChartParameterization"])
            self.assertEqual(surface.GetFieldData().GetArray("ChartCount").GetValue(0), 2)
            self.assertEqual(surface.GetPointData().GetTCoords().GetName(), "UV")


if __name__ == "__main__":
    unittest.main()
