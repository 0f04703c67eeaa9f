"""kerf.gallery: methods side by side on psb-dev models, every picture drawn and scored."""
import os
import sys
import tempfile
import unittest

import numpy
from kerf import gallery
from kerf.benchmark import BenchmarkError
from vtkmodules.util.numpy_support import vtk_to_numpy
from vtkmodules.vtkIOImage import vtkPNGReader

DATA = os.path.join(os.environ["KERF_SHARED_DATA"], "psb-dev")
MODELS = [1, 36]  # a human (15 segments in nSeg-ByModel.txt) and a cup (2)
METHODS = ["face-clustering", "watershed"]


def segment_counts():
    """Model id -> k: line N of nSeg-ByModel.txt holds model N's."""
    with open(os.path.join(DATA, "nSeg-ByModel.txt")) as f:
        return {n: int(line) for n, line in enumerate(f, start=1) if line.strip()}


class Gallery(unittest.TestCase):
    @classmethod
    def setUpClass(cls):
        cls.folder = tempfile.mkdtemp(prefix="kerf-gallery-", dir=os.environ.get("KERF_TEST_OUTPUT"))
        cls.path = os.path.join(cls.folder, "gallery.png")
        cls.lines = []
        cls.scores = gallery.gallery(DATA, METHODS, cls.path, MODELS, report=cls.lines.append)

    def test_every_model_and_method_is_scored(self):
        k = segment_counts()
        self.assertEqual(sorted(self.scores), MODELS)
        for model in MODELS:
            self.assertEqual(sorted(self.scores[model]), sorted(METHODS))
            # Face clustering cuts its merge tree at exactly k clusters.
            self.assertEqual(self.scores[model]["face-clustering"][0], k[model])
            for segments, error in self.scores[model].values():
                self.assertTrue(0.0 <= error <= 1.0)
        self.assertEqual(len(self.lines), len(MODELS) * len(METHODS))
        self.assertIn("model 36 (Cup), watershed", "\n".join(self.lines))

    def test_every_picture_is_drawn(self):
        reader = vtkPNGReader()
        reader.SetFileName(self.path)
        reader.Update()
        width, height, _ = reader.GetOutput().GetDimensions()
        self.assertEqual((width, height), (gallery.HEADER + gallery.CELL * 3, gallery.HEADER + gallery.CELL * 2))
        pixels = vtk_to_numpy(reader.GetOutput().GetPointData().GetScalars())[:, :3].reshape(height, width, 3)
        pixels = pixels[::-1]  # rows from the top
        for r in range(len(MODELS)):
            for c in range(1 + len(METHODS)):
                top = gallery.HEADER + r * gallery.CELL
                left = gallery.HEADER + c * gallery.CELL
                cell = pixels[top + 4:top + gallery.CELL - 4, left + 4:left + gallery.CELL - 4].reshape(-1, 3)
                background = numpy.all(numpy.abs(cell.astype(int) - 247) <= 2, axis=1)
                with self.subTest(model=MODELS[r], column=c):
                    # The model covers a good part of its picture.
                    self.assertGreater(1.0 - background.mean(), 0.05)
        # The human's 15 segments of model 1 show in several colours (shading aside: count hues).
        top, left = gallery.HEADER, gallery.HEADER
        human = pixels[top:top + gallery.CELL, left:left + gallery.CELL].reshape(-1, 3).astype(int)
        lit = human[(human.max(axis=1) - human.min(axis=1)) > 40]
        hues = {tuple(int(v) for v in (p * 4 // (p.max() + 1))) for p in lit}
        self.assertGreaterEqual(len(hues), 5)

    def test_unknown_method_is_refused(self):
        with self.assertRaises(BenchmarkError):
            gallery.gallery(DATA, ["telepathy"], os.path.join(self.folder, "never.png"), MODELS)
        self.assertFalse(os.path.exists(os.path.join(self.folder, "never.png")))


if __name__ == "__main__":
    if not os.path.isdir(os.path.join(DATA, "off")):
        print("../shared/data/psb-dev is absent: skipped")
        sys.exit(125)
    unittest.main(argv=[sys.argv[0]])
