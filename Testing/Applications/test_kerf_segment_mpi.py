"""Runs `kerf segment FOLDER` under mpirun on 2 ranks and checks it against the run without mpirun:
the same files bit for bit, the meshes dealt out by size, one report of a failure, and a single mesh
refused."""
import csv
import os
import shutil
import subprocess
import sys
import tempfile
import unittest

KERF = sys.argv[1]
MPIRUN = sys.argv[2]
SOURCE = os.environ["KERF_SOURCE_DIR"]


def run(*args, ranks=None):
    launcher = [MPIRUN, "--allow-run-as-root", "--oversubscribe", "-np", str(ranks)] if ranks else []
    return subprocess.run([*launcher, KERF, *args], capture_output=True, text=True, timeout=600)


def summary(folder):
    with open(os.path.join(folder, "summary.csv"), newline="") as f:
        return list(csv.DictReader(f))


class SegmentOverRanks(unittest.TestCase):
    def setUp(self):
        self.folder = tempfile.mkdtemp(prefix="kerf-segment-mpi-", dir=os.environ.get("KERF_TEST_OUTPUT"))
        self.meshes = os.path.join(self.folder, "meshes")
        os.makedirs(self.meshes)
        for name in ("camel.off", "elephant.off", "hand.off"):
            shutil.copy(os.path.join(SOURCE, "Data", name), self.meshes)

    def segment(self, out, ranks=None):
        return run("segment", self.meshes, "--method", "k-means", "-k", "3", "-o", os.path.join(self.folder, out),
                   ranks=ranks)

    def test_two_ranks_write_what_one_process_writes(self):
        serial, parallel = self.segment("serial"), self.segment("parallel", ranks=2)
        self.assertEqual(serial.returncode, 0, serial.stderr)
        self.assertEqual(parallel.returncode, 0, parallel.stderr)
        for stem in ("camel", "elephant", "hand"):
            with open(os.path.join(self.folder, "serial", stem + ".seg"), "rb") as a, \
                    open(os.path.join(self.folder, "parallel", stem + ".seg"), "rb") as b:
                self.assertEqual(a.read(), b.read(), stem)
        rows, parallel_rows = summary(os.path.join(self.folder, "serial")), summary(os.path.join(self.folder, "parallel"))

        def kept(row):
            return row["Mesh"], row["Triangles"], row["Segments"], row["Error"]

        self.assertEqual([kept(r) for r in rows], [kept(r) for r in parallel_rows])
        self.assertEqual([r["Mesh"] for r in rows], ["camel.off", "elephant.off", "hand.off"])
        self.assertEqual([r["Rank"] for r in rows], ["0", "0", "0"])
        # The largest file (camel) first to rank 0, then the elephant to the empty rank 1, then the
        # hand to rank 1, which has fewer bytes than rank 0.
        sizes = [os.path.getsize(os.path.join(self.meshes, r["Mesh"])) for r in rows]
        self.assertGreater(sizes[0], sizes[1])
        self.assertLess(sizes[1] + sizes[2], sizes[0])
        self.assertEqual([r["Rank"] for r in parallel_rows], ["0", "1", "1"])
        self.assertIn("[1/3] k-means segmentation of camel.off: 3 segments over 19536 triangles", parallel.stdout)
        self.assertRegex(parallel.stdout, r"\[2/3\] k-means segmentation of elephant\.off: 3 segments over \d+ "
                                          r"triangles in [\d.]+ ms \(rank 1\)")
        self.assertRegex(parallel.stdout, r"\[3/3\] k-means segmentation of hand\.off: .* \(rank 1\)")
        self.assertNotIn("(rank", serial.stdout)

    def test_a_failure_on_one_rank_is_reported_once_and_the_others_go_on(self):
        shutil.copy(os.path.join(SOURCE, "Testing", "Data", "Input", "truncated.off"), self.meshes)
        result = self.segment("out", ranks=2)
        self.assertEqual(result.returncode, 1)
        self.assertEqual(result.stderr.count("kerf: error:"), 1, result.stderr)
        self.assertIn("kerf: error: 1 of 4 meshes failed; the first: truncated.off: cannot read the mesh",
                      result.stderr)
        rows = summary(os.path.join(self.folder, "out"))
        self.assertEqual([r["Mesh"] for r in rows], ["camel.off", "elephant.off", "hand.off", "truncated.off"])
        self.assertEqual([r["Error"] == "" for r in rows], [True, True, True, False])
        self.assertEqual(sorted(os.listdir(os.path.join(self.folder, "out"))),
                         ["camel.seg", "camel.vtp", "elephant.seg", "elephant.vtp", "hand.seg", "hand.vtp",
                          "summary.csv"])

    def test_one_mesh_under_mpirun_is_refused(self):
        result = run("segment", os.path.join(self.meshes, "hand.off"), "-k", "3", "--seg",
                     os.path.join(self.folder, "hand.seg"), ranks=2)
        self.assertNotEqual(result.returncode, 0)
        self.assertIn("under mpirun, segment takes a folder", result.stderr)
        self.assertFalse(os.path.exists(os.path.join(self.folder, "hand.seg")))
        result = run("segment", os.path.join(self.meshes, "hand.off"), "-k", "3", "--method", "k-means", "--seg",
                     os.path.join(self.folder, "hand.seg"), ranks=1)
        self.assertEqual(result.returncode, 0, result.stderr)
        with open(os.path.join(self.folder, "hand.seg")) as f:
            self.assertEqual(len(f.readlines()), 2390)


if __name__ == "__main__":
    unittest.main(argv=[sys.argv[0]])
