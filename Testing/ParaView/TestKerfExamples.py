# The pvpython examples of Documentation/examples, run as a user would and checked by their numbers.
import os
import sys
import unittest

from paraview import simple

sys.path.insert(0, os.path.join(os.environ["KERF_SOURCE_DIR"], "Documentation", "examples"))
simple.LoadPlugin(os.environ["KERF_PLUGIN"])

import best_isoline  # noqa: E402
import cut_from_stroke  # noqa: E402

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


if __name__ == "__main__":
    unittest.main()
