"""Runs the kerf program as a user would and checks its outputs and exit codes."""
import os
import subprocess
import sys
import tempfile
import unittest

from vtkmodules.vtkIOGeometry import vtkOBJReader
from vtkmodules.vtkIOPLY import vtkPLYReader
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
        for command in ("showcase", "cut", "unwrap", "segment", "descriptors", "info", "convert", "render",
                        "benchmark"):
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
                     "--weighting", "concavity", "--timings")
        self.assertEqual(result.returncode, 0, result.stderr)
        self.assertIn("1 curve (1 closed)", result.stdout)
        self.assertIn("2 segments", result.stdout)
        self.assertIn("time: read mesh", result.stdout)
        self.assertIn("write surface", result.stdout)
        result = run("cut", os.path.join(SOURCE, "Data", "camel.off"), "--stroke",
                     os.path.join(SOURCE, "Data", "camel-neck-stroke.vtk"), "--formulation", "fastest")
        self.assertEqual(result.returncode, 1)
        self.assertIn("--formulation must be", result.stderr)
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
        self.assertIn("2 segments (5859, 13671 triangles)", result.stdout)

    def unwrap_camel(self, *extra):
        """The camel cut along the neck stroke (kerf cut --curve), then kerf unwrap along that cut."""
        curve = os.path.join(self.folder, "neck-curve.vtp")
        result = run("cut", os.path.join(SOURCE, "Data", "camel.off"), "--stroke",
                     os.path.join(SOURCE, "Data", "camel-neck-stroke.vtk"), "--curve", curve, "--quiet")
        self.assertEqual(result.returncode, 0, result.stderr)
        return run("unwrap", os.path.join(SOURCE, "Data", "camel.off"), "--curves", curve, *extra)

    def test_unwrap_writes_an_obj_with_texture_coordinates_and_a_picture(self):
        obj = os.path.join(self.folder, "camel-unwrapped.obj")
        vtp = os.path.join(self.folder, "camel-unwrapped.vtp")
        picture = os.path.join(self.folder, "camel-unwrapped.png")
        result = self.unwrap_camel("-o", obj, "--png", picture, "--margin", "0.02")
        self.assertEqual(result.returncode, 0, result.stderr)
        # The head and the body, the legs and other protrusions given seams to the neck; a few
        # triangles flip at seam tips (baseline 4).
        self.assertIn("2 charts (0 cut into disks, 13 seams added)", result.stdout)
        self.assertIn("4 flipped triangles", result.stdout)
        self.assertIn("0 overlapping chart pairs", result.stdout)
        with open(picture, "rb") as png:
            self.assertEqual(png.read(8), b"\x89PNG\r\n\x1a\n")
        self.assertGreater(os.path.getsize(picture), 50000)
        # The OBJ: one vt per v (cut vertices are duplicated, one copy per chart), faces v/vt.
        vertices, uvs, faces = [], [], []
        with open(obj) as lines:
            for line in lines:
                words = line.split()
                if words and words[0] == "v":
                    vertices.append([float(w) for w in words[1:4]])
                elif words and words[0] == "vt":
                    uvs.append([float(w) for w in words[1:3]])
                elif words and words[0] == "f":
                    corners = [w.split("/") for w in words[1:]]
                    self.assertEqual(len(corners), 3)
                    for corner in corners:
                        self.assertEqual(corner[0], corner[1])
                    faces.append([int(c[0]) - 1 for c in corners])
        self.assertEqual(len(uvs), len(vertices))
        self.assertGreater(len(faces), 19536)  # scissor splits the triangles along the cut
        self.assertGreater(len(vertices), 9770)
        for u, v in uvs:
            self.assertTrue(0.02 - 1e-6 <= u <= 0.98 + 1e-6 and 0.02 - 1e-6 <= v <= 0.98 + 1e-6, (u, v))
        # The same run written as VTP (full precision) has the UVs the OBJ holds, and so does
        # VTK's own OBJ reader (what MeshLab and Blender read as well).
        self.assertEqual(self.unwrap_camel("-o", vtp, "--margin", "0.02", "--quiet").returncode, 0)
        reader = vtkXMLPolyDataReader()
        reader.SetFileName(vtp)
        reader.Update()
        exact = reader.GetOutput().GetPointData().GetTCoords()
        self.assertEqual(exact.GetName(), "UV")
        self.assertEqual(exact.GetNumberOfTuples(), len(uvs))
        obj_reader = vtkOBJReader()
        obj_reader.SetFileName(obj)
        obj_reader.Update()
        read_back = obj_reader.GetOutput().GetPointData().GetTCoords()
        self.assertEqual(obj_reader.GetOutput().GetNumberOfPolys(), len(faces))
        worst = 0.0
        for point in range(len(uvs)):
            for k in range(2):
                worst = max(worst, abs(exact.GetComponent(point, k) - uvs[point][k]))
        self.assertLess(worst, 1e-5)
        self.assertEqual(read_back.GetNumberOfTuples(), len(uvs))

    def test_unwrap_flattens_with_linabf_on_request(self):
        obj = os.path.join(self.folder, "camel-linabf.obj")
        result = self.unwrap_camel("-o", obj, "--method", "linabf")
        self.assertEqual(result.returncode, 0, result.stderr)
        self.assertIn("2 charts (0 cut into disks", result.stdout)
        self.assertIn("0 overlapping chart pairs", result.stdout)
        self.assertTrue(os.path.exists(obj))
        result = self.unwrap_camel("-o", obj, "--method", "abf")
        self.assertEqual(result.returncode, 1)
        self.assertIn("--method must be lscm or linabf, got 'abf'", result.stderr)

    def test_unwrap_cuts_charts_into_disks_or_refuses_them(self):
        # An open curve over two camel vertices separates nothing: the one chart is the closed
        # camel, cut into a disk (and given seams) by default, refused with --refuse-non-disks.
        curve = os.path.join(self.folder, "open.vtk")
        with open(curve, "w") as f:
            f.write("# vtk DataFile Version 3.0\nopen\nASCII\nDATASET POLYDATA\nPOINTS 2 double\n"
                    + self.camel_vertex(0) + "\n" + self.camel_vertex(1) + "\nLINES 1 3\n2 0 1\n")
        out = os.path.join(self.folder, "whole.obj")
        result = run("unwrap", os.path.join(SOURCE, "Data", "camel.off"), "--curves", curve, "-o", out)
        self.assertEqual(result.returncode, 0, result.stderr)
        self.assertIn("1 chart (1 cut into disks", result.stdout)
        self.assertIn("0 overlapping chart pairs", result.stdout)
        self.assertTrue(os.path.exists(out))
        never = os.path.join(self.folder, "never.obj")
        result = run("unwrap", os.path.join(SOURCE, "Data", "camel.off"), "--curves", curve, "-o", never,
                     "--refuse-non-disks")
        self.assertEqual(result.returncode, 1)
        self.assertIn("kerf: error: cannot flatten the charts", result.stderr)
        self.assertIn("chart 0: it has 0 boundary loops and genus 0", result.stderr)
        self.assertFalse(os.path.exists(never))
        far = os.path.join(self.folder, "far.vtk")
        with open(far, "w") as f:
            f.write("# vtk DataFile Version 3.0\nfar\nASCII\nDATASET POLYDATA\nPOINTS 2 double\n"
                    "5 5 5\n6 5 5\nLINES 1 3\n2 0 1\n")
        result = run("unwrap", os.path.join(SOURCE, "Data", "camel.off"), "--curves", far, "-o", never)
        self.assertEqual(result.returncode, 1)
        self.assertIn("kerf: error: cannot cut the mesh along the curves", result.stderr)
        self.assertNotIn("ERROR:", result.stderr)
        result = run("unwrap", os.path.join(SOURCE, "Data", "camel.off"), "-o", never)
        self.assertEqual(result.returncode, 1)
        self.assertIn("--curves", result.stderr)

    @staticmethod
    def camel_vertex(index, mesh="camel.off"):
        with open(os.path.join(SOURCE, "Data", mesh)) as off:
            lines = [line for line in off.read().split("\n") if line.strip()]
        return lines[2 + index]

    def test_unwrap_cuts_the_handles_of_the_elephant(self):
        # The elephant has genus 3 (trunk and tusks joined to the head): one chart, cut into a
        # disk along loops through its handles, flattened without overlaps.
        curve = os.path.join(self.folder, "elephant-open.vtk")
        with open(curve, "w") as f:
            f.write("# vtk DataFile Version 3.0\nopen\nASCII\nDATASET POLYDATA\nPOINTS 2 double\n"
                    + self.camel_vertex(0, "elephant.off") + "\n" + self.camel_vertex(1, "elephant.off")
                    + "\nLINES 1 3\n2 0 1\n")
        out = os.path.join(self.folder, "elephant.ply")
        result = run("unwrap", os.path.join(SOURCE, "Data", "elephant.off"), "--curves", curve, "-o", out)
        self.assertEqual(result.returncode, 0, result.stderr)
        self.assertIn("1 chart (1 cut into disks", result.stdout)
        self.assertIn("0 overlapping chart pairs", result.stdout)
        # 5,558 triangles, and those the curve crosses split by the scissor (baseline).
        self.assertIn("5936 triangles", result.stdout)
        # The PLY holds the texture coordinates (u, v) of every point, as VTK's reader reads them.
        reader = vtkPLYReader()
        reader.SetFileName(out)
        reader.Update()
        self.assertEqual(reader.GetOutput().GetNumberOfPolys(), 5936)
        self.assertEqual(reader.GetOutput().GetPointData().GetTCoords().GetNumberOfTuples(),
                         reader.GetOutput().GetNumberOfPoints())

    def test_convert_round_trip_keeps_the_surface(self):
        for extension in (".ply", ".obj", ".stl", ".vtk", ".vtp", ".off"):
            converted = os.path.join(self.folder, "hand" + extension)
            result = run("convert", os.path.join(SOURCE, "Data", "hand.off"), converted, "--quiet")
            self.assertEqual(result.returncode, 0, result.stderr)
            info = run("info", converted)
            self.assertEqual(info.returncode, 0, info.stdout + info.stderr)
            self.assertIn("points: 1197", info.stdout)
            self.assertIn("2390 polygons", info.stdout)

    def test_segment_writes_labels_as_a_mesh_array_a_seg_file_and_a_picture(self):
        camel = os.path.join(SOURCE, "Data", "camel.off")
        surface, seg = os.path.join(self.folder, "camel.vtp"), os.path.join(self.folder, "camel.seg")
        picture = os.path.join(self.folder, "camel.png")
        result = run("segment", camel, "-k", "5", "-o", surface, "--seg", seg, "--png", picture)
        self.assertEqual(result.returncode, 0, result.stderr)
        self.assertIn("ensemble segmentation of " + camel + ": 5 segments over 19536 triangles", result.stdout)
        with open(seg) as f:
            labels = [int(line) for line in f]
        self.assertEqual(len(labels), 19536)
        self.assertEqual(sorted(set(labels)), [0, 1, 2, 3, 4])
        reader = vtkXMLPolyDataReader()
        reader.SetFileName(surface)
        reader.Update()
        segment = reader.GetOutput().GetCellData().GetArray("Segment")
        self.assertEqual([int(segment.GetValue(c)) for c in range(segment.GetNumberOfTuples())], labels)
        with open(picture, "rb") as png:
            self.assertEqual(png.read(8), b"\x89PNG\r\n\x1a\n")
        # Every other method reaches k on the camel.
        for method in ("consensus-cuts", "spectral", "k-means", "face-clustering", "watershed", "convex-flooding"):
            out = os.path.join(self.folder, method + ".seg")
            result = run("segment", camel, "--method", method, "-k", "4", "--seg", out, "--quiet")
            self.assertEqual(result.returncode, 0, method + ": " + result.stderr)
            self.assertEqual(result.stdout, "")
            with open(out) as f:
                labels = [int(line) for line in f]
            self.assertEqual(len(labels), 19536, method)
            self.assertEqual(len(set(labels)), 4, method)
        # Core extraction chooses the number of parts itself: the camel's six; -k is refused.
        out = os.path.join(self.folder, "core-extraction.seg")
        result = run("segment", camel, "--method", "core-extraction", "--seg", out)
        self.assertEqual(result.returncode, 0, result.stderr)
        self.assertIn("core-extraction segmentation of " + camel + ": 6 segments over 19536 triangles", result.stdout)
        with open(out) as f:
            self.assertEqual(sorted(set(int(line) for line in f)), list(range(6)))
        result = run("segment", camel, "--method", "core-extraction", "-k", "4")
        self.assertEqual(result.returncode, 1)
        self.assertIn("core-extraction chooses the number of segments itself", result.stderr)
        # --auto: the ensemble chooses the count among 5 to 11 (the camel: 9, measured), and its labels are
        # the ensemble's at that count; with -k or another method it is refused.
        chosen = os.path.join(self.folder, "auto.seg")
        result = run("segment", camel, "--auto", "--seg", chosen, "--quiet")
        self.assertEqual(result.returncode, 0, result.stderr)
        with open(chosen) as f:
            labels = [int(line) for line in f]
        count = len(set(labels))
        self.assertEqual(sorted(set(labels)), list(range(count)))
        self.assertTrue(5 <= count <= 11, count)
        fixed = os.path.join(self.folder, "fixed.seg")
        self.assertEqual(run("segment", camel, "-k", str(count), "--seg", fixed, "--quiet").returncode, 0)
        with open(fixed) as f:
            self.assertEqual([int(line) for line in f], labels)
        result = run("segment", camel, "--auto", "-k", "4")
        self.assertEqual(result.returncode, 1)
        self.assertIn("one of them", result.stderr)
        # A convex surface has no parts: an icosahedron (20 faces) stays one segment with --auto.
        golden = (1.0 + 5.0 ** 0.5) / 2.0
        corners = [(0, s, t * golden) for s in (-1, 1) for t in (-1, 1)]
        corners = [p for c in corners for p in (c, (c[1], c[2], c[0]), (c[2], c[0], c[1]))]
        faces = []
        for a in range(12):
            for b in range(a + 1, 12):
                for c in range(b + 1, 12):
                    if all(abs(sum((corners[i][d] - corners[j][d]) ** 2 for d in range(3)) - 4.0) < 1e-9
                           for i, j in ((a, b), (b, c), (a, c))):
                        # Outward: the normal points away from the centre.
                        u = [corners[b][d] - corners[a][d] for d in range(3)]
                        v = [corners[c][d] - corners[a][d] for d in range(3)]
                        n = (u[1] * v[2] - u[2] * v[1], u[2] * v[0] - u[0] * v[2], u[0] * v[1] - u[1] * v[0])
                        outward = sum(n[d] * corners[a][d] for d in range(3)) > 0
                        faces.append((a, b, c) if outward else (a, c, b))
        self.assertEqual(len(faces), 20)
        icosahedron = os.path.join(self.folder, "icosahedron.off")
        with open(icosahedron, "w") as f:
            f.write("OFF\n12 20 0\n")
            f.writelines("%r %r %r\n" % p for p in corners)
            f.writelines("3 %d %d %d\n" % t for t in faces)
        result = run("segment", icosahedron, "--auto", "-o", os.path.join(self.folder, "icosahedron.vtp"))
        self.assertEqual(result.returncode, 0, result.stderr)
        self.assertIn("ensemble segmentation of " + icosahedron + ": 1 segment over 20 triangles", result.stdout)
        result = run("segment", camel, "--auto", "--method", "spectral")
        self.assertEqual(result.returncode, 1)
        self.assertIn("--auto is for the methods that can choose the number of segments: ensemble", result.stderr)
        self.assertIn("  ensemble, consensus-cuts, spectral, k-means", run("segment", "--help").stdout)
        result = run("segment", camel, "--method", "nope")
        self.assertEqual(result.returncode, 1)
        self.assertIn("unknown method 'nope' for segment (ensemble, consensus-cuts", result.stderr)
        result = run("segment", camel, "-k", "0")
        self.assertEqual(result.returncode, 1)
        self.assertIn("expects a number from 1", result.stderr)
        result = run("segment", os.path.join(SOURCE, "Testing", "Data", "Input", "truncated.off"))
        self.assertEqual(result.returncode, 1)
        self.assertIn("kerf: error: cannot read the mesh", result.stderr)

    def test_segment_a_folder_reports_each_mesh_and_goes_on_after_a_failure(self):
        import shutil
        folder, out = os.path.join(self.folder, "meshes"), os.path.join(self.folder, "segmented")
        os.makedirs(folder)
        for name in ("camel.off", "hand.off"):
            shutil.copy(os.path.join(SOURCE, "Data", name), folder)
        with open(os.path.join(folder, "notes.txt"), "w") as f:
            f.write("not a mesh\n")
        result = run("segment", folder, "--method", "k-means", "-k", "3", "-o", out)
        self.assertEqual(result.returncode, 0, result.stderr)
        self.assertIn("[1/2] k-means segmentation of camel.off: 3 segments over 19536 triangles", result.stdout)
        self.assertIn("[2/2] k-means segmentation of hand.off: 3 segments over 2390 triangles", result.stdout)
        self.assertEqual(sorted(os.listdir(out)), ["camel.seg", "camel.vtp", "hand.seg", "hand.vtp", "summary.csv"])
        import csv
        with open(os.path.join(out, "summary.csv"), newline="") as f:
            rows = list(csv.DictReader(f))
        self.assertEqual([(r["Mesh"], r["Triangles"], r["Segments"], r["Rank"], r["Error"]) for r in rows],
                         [("camel.off", "19536", "3", "0", ""), ("hand.off", "2390", "3", "0", "")])
        self.assertGreater(float(rows[0]["Milliseconds"]), 0.0)
        with open(os.path.join(out, "hand.seg")) as f:
            self.assertEqual(len(f.readlines()), 2390)
        shutil.copy(os.path.join(SOURCE, "Testing", "Data", "Input", "truncated.off"), folder)
        result = run("segment", folder, "--method", "k-means", "-k", "3", "-o", out)
        self.assertEqual(result.returncode, 1)
        self.assertIn("[3/3] truncated.off failed: cannot read the mesh", result.stdout)
        self.assertIn("kerf: error: 1 of 3 meshes failed; the first: truncated.off", result.stderr)
        with open(os.path.join(out, "summary.csv"), newline="") as f:
            rows = list(csv.DictReader(f))
        self.assertEqual([r["Mesh"] for r in rows], ["camel.off", "hand.off", "truncated.off"])
        self.assertEqual((rows[2]["Triangles"], rows[2]["Segments"]), ("0", "0"))
        self.assertTrue(rows[2]["Error"].startswith("cannot read the mesh"), rows[2]["Error"])
        self.assertEqual(run("segment", folder, "--seg", "x.seg").returncode, 1)

    def test_threads_limit_kerf_and_leave_the_labels_as_they_are(self):
        """--threads N limits Kerf's threads for the whole command; the labels are the same on one
        thread and two (the ensemble's members run in parallel), and a bad count is refused."""
        hand = os.path.join(SOURCE, "Data", "hand.off")
        labels = []
        for threads in ("1", "2"):
            seg = os.path.join(self.folder, "hand-" + threads + ".seg")
            result = run("segment", hand, "--auto", "--threads", threads, "--seg", seg, "--quiet")
            self.assertEqual(result.returncode, 0, result.stderr)
            with open(seg) as f:
                labels.append([int(line) for line in f])
        self.assertEqual(len(labels[0]), 2390)
        self.assertGreater(len(set(labels[0])), 1)
        self.assertEqual(labels[0], labels[1])
        for bad in ("-1", "two", "2000"):
            result = run("segment", hand, "--threads", bad, "--seg", os.path.join(self.folder, "x.seg"))
            self.assertEqual(result.returncode, 1, bad)
            self.assertIn("--threads expects a number", result.stderr)
        self.assertIn("--threads N", run("--help").stdout)

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
