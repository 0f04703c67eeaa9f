"""Runs the kerf program as a user would and checks its outputs and exit codes."""
import os
import subprocess
import sys
import tempfile
import unittest

from vtkmodules.vtkIOXML import vtkXMLPolyDataReader

KERF = sys.argv[1]
SOURCE = os.environ["KERF_SOURCE_DIR"]


def run(*args):
    return subprocess.run([KERF, *args], capture_output=True, text=True, timeout=300)


class CommandLine(unittest.TestCase):
    def setUp(self):
        self.folder = tempfile.mkdtemp(prefix="kerf-cli-", dir=os.environ.get("KERF_TEST_OUTPUT"))

    def test_help_lists_every_command(self):
        result = run("--help")
        self.assertEqual(result.returncode, 0)
        for command in ("showcase", "cut", "descriptors", "info", "convert", "render", "benchmark"):
            self.assertIn(command, result.stdout)
        self.assertEqual(run("descriptors", "--help").returncode, 0)
        self.assertEqual(run().returncode, 2)

    def test_showcase_writes_surface_curve_picture_and_summary(self):
        result = run("showcase", "-o", self.folder)
        self.assertEqual(result.returncode, 0, result.stderr)
        self.assertIn("9770 points, 19536 triangles", result.stdout)
        self.assertIn("2 segments", result.stdout)
        surface = os.path.join(self.folder, "camel-cut.vtp")
        curve = os.path.join(self.folder, "camel-cut-curve.vtp")
        picture = os.path.join(self.folder, "camel-cut.png")
        for path in (surface, curve, picture):
            self.assertIn(path, result.stdout)
        with open(picture, "rb") as png:
            self.assertEqual(png.read(8), b"\x89PNG\r\n\x1a\n")
        self.assertGreater(os.path.getsize(picture), 50000)
        reader = vtkXMLPolyDataReader()
        reader.SetFileName(surface)
        reader.Update()
        data = reader.GetOutput()
        self.assertEqual(data.GetNumberOfPoints(), 9770)
        self.assertEqual(data.GetNumberOfCells(), 19536)
        names = {data.GetPointData().GetArrayName(i) for i in range(data.GetPointData().GetNumberOfArrays())}
        self.assertTrue({"Normals", "MaximumCurvature", "MinimumCurvature", "MeanCurvature",
                         "GaussianCurvature", "Concave", "NormalConeAngle", "HarmonicField",
                         "MaximumCurvatureDirection", "MinimumCurvatureDirection"} <= names)
        cells = {data.GetCellData().GetArrayName(i) for i in range(data.GetCellData().GetNumberOfArrays())}
        self.assertTrue({"Segment", "FieldGradient", "FieldGradientMagnitude"} <= cells)
        segments = data.GetCellData().GetArray("Segment")
        self.assertEqual(segments.GetRange(), (0.0, 1.0))
        reader.SetFileName(curve)
        reader.Update()
        self.assertEqual(reader.GetOutput().GetNumberOfCells(), 1)
        self.assertEqual(reader.GetOutput().GetCellData().GetArray("Closed").GetValue(0), 1)

    def test_descriptors_and_cut_commands(self):
        out = os.path.join(self.folder, "hand-descriptors.vtp")
        result = run("descriptors", os.path.join(SOURCE, "Data", "hand.off"), "-o", out,
                     "--png", os.path.join(self.folder, "hand.png"))
        self.assertEqual(result.returncode, 0, result.stderr)
        self.assertIn("1197 points, 2390 triangles", result.stdout)
        cut = os.path.join(self.folder, "camel-cut.vtk")
        result = run("cut", os.path.join(SOURCE, "Data", "camel.off"), "--stroke",
                     os.path.join(SOURCE, "Data", "camel-neck-stroke.vtk"), "-o", cut,
                     "--weighting", "concavity")
        self.assertEqual(result.returncode, 0, result.stderr)
        self.assertIn("1 curve (1 closed)", result.stdout)
        self.assertIn("2 segments", result.stdout)
        result = run("cut", os.path.join(SOURCE, "Data", "camel.off"), "--stroke",
                     os.path.join(SOURCE, "Data", "camel-neck-stroke.vtk"), "--weighting", "mystery")
        self.assertEqual(result.returncode, 1)
        self.assertIn("--weighting must be", result.stderr)

    def test_cut_ending_on_a_hole_has_no_sliver_segment(self):
        # The camel with the triangles round neck vertex 8101 removed: the concavity-aware cut runs
        # through the hole, and a triangle it crosses there, with its uncrossed edge on the hole,
        # touches neither side. It joins a side instead of being a one-triangle third segment.
        with open(os.path.join(SOURCE, "Data", "camel.off")) as off:
            lines = [line for line in off.read().split("\n") if line.strip()]
        counts = lines[1].split()
        points = int(counts[0])
        faces = [line for line in lines[2 + points:2 + points + int(counts[1])] if "8101" not in line.split()[1:]]
        self.assertEqual(len(faces), 19536 - 6)
        holed = os.path.join(self.folder, "camel-hole.off")
        with open(holed, "w") as off:
            off.write("OFF\n%d %d 0\n" % (points, len(faces)))
            off.write("\n".join(lines[2:2 + points] + faces) + "\n")
        result = run("cut", holed, "--stroke", os.path.join(SOURCE, "Data", "camel-neck-stroke.vtk"),
                     "--weighting", "concavity")
        self.assertEqual(result.returncode, 0, result.stderr)
        self.assertIn("2 segments (5862, 13668 triangles)", result.stdout)

    def test_convert_round_trip_keeps_the_surface(self):
        for extension in (".ply", ".obj", ".stl", ".vtk", ".vtp", ".off"):
            converted = os.path.join(self.folder, "hand" + extension)
            result = run("convert", os.path.join(SOURCE, "Data", "hand.off"), converted, "--quiet")
            self.assertEqual(result.returncode, 0, result.stderr)
            info = run("info", converted)
            self.assertEqual(info.returncode, 0, info.stdout + info.stderr)
            self.assertIn("points: 1197", info.stdout)
            self.assertIn("2390 polygons", info.stdout)

    def test_errors_exit_with_one_and_a_message(self):
        result = run("info", os.path.join(SOURCE, "Testing", "Data", "Input", "truncated.off"))
        self.assertEqual(result.returncode, 1)
        self.assertIn("kerf: error: cannot read the mesh", result.stderr)
        self.assertIn("ends after 3 of 4 vertices", result.stderr)
        self.assertNotIn("ERROR:", result.stderr)
        result = run("frobnicate")
        self.assertEqual(result.returncode, 1)
        self.assertIn("unknown command", result.stderr)
        result = run("render", os.path.join(SOURCE, "Data", "hand.off"), "-o",
                     os.path.join(self.folder, "x.png"), "--array", "Nope")
        self.assertEqual(result.returncode, 1)
        self.assertIn("no one-component point or cell array named 'Nope'", result.stderr)
        result = run("descriptors", os.path.join(SOURCE, "Data", "hand.off"), "--size", "banana",
                     "--png", os.path.join(self.folder, "y.png"))
        self.assertEqual(result.returncode, 1)
        self.assertIn("--size expects", result.stderr)

    def test_info_reports_a_refused_surface(self):
        bad = os.path.join(self.folder, "nonmanifold.off")
        with open(bad, "w") as f:
            f.write("OFF\n5 3 0\n0 0 0\n1 0 0\n0 1 0\n0 -1 0\n0 0 1\n3 0 1 2\n3 1 0 3\n3 0 1 4\n")
        result = run("info", bad)
        self.assertEqual(result.returncode, 1)
        self.assertIn("non-manifold", result.stdout)


if __name__ == "__main__":
    unittest.main(argv=[sys.argv[0]])
