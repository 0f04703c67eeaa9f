"""The benchmark runner: the human baseline reproduces the benchmark's numbers, and the C++ and
Python runners agree row for row."""
import csv
import os
import subprocess
import sys
import tempfile
import unittest

DATA = os.path.join(os.environ["KERF_SHARED_DATA"], "psb-dev")
PROGRAM = os.environ["KERF_PROGRAM"]


def readme_human_rand_index():
    """Model id -> the "human 1-RI" column of psb-dev/README.md."""
    values = {}
    with open(os.path.join(DATA, "README.md")) as readme:
        for line in readme:
            cells = [c.strip() for c in line.split("|")]
            if len(cells) > 7 and cells[1].isdigit():
                values[int(cells[1])] = float(cells[7])
    return values


def read_rows(path):
    with open(path) as f:
        return list(csv.DictReader(f))


class BenchmarkRunner(unittest.TestCase):
    @classmethod
    def setUpClass(cls):
        cls.folder = tempfile.mkdtemp(prefix="kerf-benchmark-", dir=os.environ.get("KERF_TEST_OUTPUT"))
        cls.cli = subprocess.run([PROGRAM, "benchmark", "--data", DATA, "--method", "human",
                                  "--jobs", "2", "--no-pictures", "-o", os.path.join(cls.folder, "cli")],
                                 capture_output=True, text=True, timeout=600)

    def test_human_baseline_matches_the_benchmark(self):
        self.assertEqual(self.cli.returncode, 0, self.cli.stderr)
        expected = readme_human_rand_index()
        rows = read_rows(os.path.join(self.folder, "cli", "results.csv"))
        self.assertEqual(sorted(int(r["Model"]) for r in rows), sorted(expected))
        for row in rows:
            model = int(row["Model"])
            self.assertEqual(round(float(row["RandIndexError"]), 3), expected[model], "model %d" % model)
            self.assertEqual(row["Method"], "human")
            humans = len([f for f in os.listdir(os.path.join(DATA, "seg", str(model))) if f.endswith(".seg")])
            self.assertEqual(int(row["Comparisons"]), humans * (humans - 1) // 2)
        summary = {r["Category"]: r for r in read_rows(os.path.join(self.folder, "cli", "summary.csv"))}
        self.assertEqual(int(summary["all"]["Models"]), len(expected))
        mean = sum(expected.values()) / len(expected)
        self.assertAlmostEqual(float(summary["all"]["RandIndexError"]), mean, delta=0.0006)
        self.assertEqual(int(summary["Bearing"]["Models"]), 3)
        self.assertIn("[ 40/40]", self.cli.stdout)

    def test_python_runner_agrees_with_the_program(self):
        out = os.path.join(self.folder, "python")
        result = subprocess.run([sys.executable, "-m", "kerf.benchmark", "--data", DATA,
                                 "--models", "9,142,353", "--jobs", "2", "-o", out],
                                capture_output=True, text=True, timeout=600)
        self.assertEqual(result.returncode, 0, result.stderr)
        ours = {r["Model"]: r for r in read_rows(os.path.join(out, "results.csv"))}
        cli = {r["Model"]: r for r in read_rows(os.path.join(self.folder, "cli", "results.csv"))}
        self.assertEqual(sorted(ours), ["142", "353", "9"])
        for model, row in ours.items():
            self.assertEqual(row, cli[model])
        for model in ("9", "142", "353"):
            with open(os.path.join(out, "pictures", model + ".png"), "rb") as png:
                self.assertEqual(png.read(8), b"\x89PNG\r\n\x1a\n")

    def test_easy_mesh_cutting_from_simulated_strokes(self):
        def run(method, parameters):
            out = os.path.join(self.folder, method + parameters)
            command = [PROGRAM, "benchmark", "--data", DATA, "--method", method, "--jobs", "2", "--no-pictures",
                       "-o", out] + (["--parameters", parameters] if parameters else [])
            result = subprocess.run(command, capture_output=True, text=True, timeout=1200)
            self.assertEqual(result.returncode, 0, result.stderr)
            return read_rows(os.path.join(out, "results.csv"))

        def mean(rows, column):
            return sum(float(r[column]) for r in rows) / len(rows)

        # Over psb-dev, every human in turn as the input: one stroke per segment (along its faces
        # at least a fifth as far inside as its innermost one) gives a mean fidelity of 0.125 where
        # the fronts meet (placement=fronts, the paper's rule), 0.095 with a minimum cut through
        # their band, 0.054 with the random walks alone (cut-band=0) and 0.048 with the walks and
        # the cut through their band (the default; the issue asks below 0.05; against the other
        # humans 0.153, 0.121 and 0.118, the goal below 0.15); three rounds of corrections 0.020,
        # with the snakes 0.020 (the worst model 0.054 and 0.049, a bust), the input's number of
        # segments reproduced in 97.0% of the runs with the snakes; 1 - Rand index against the
        # other humans 0.115 and 0.115.
        fronts = run("region-growing", "corrections=0;placement=fronts")
        cut = run("region-growing", "corrections=0;placement=minimum-cut")
        first = run("region-growing", "corrections=0")
        grown = run("region-growing", "")
        refined = run("region-growing+snakes", "")
        self.assertEqual(len(refined), len(readme_human_rand_index()))
        self.assertGreater(mean(fronts, "Fidelity"), 0.10)
        self.assertLess(mean(fronts, "Fidelity"), 0.15)
        self.assertGreater(mean(cut, "Fidelity"), 0.085)
        self.assertLess(mean(cut, "Fidelity"), mean(fronts, "Fidelity") - 0.02)
        self.assertLess(mean(cut, "RandIndexError"), mean(fronts, "RandIndexError"))
        self.assertLess(mean(first, "Fidelity"), 0.05)
        self.assertLess(mean(first, "Fidelity"), mean(cut, "Fidelity") - 0.04)
        self.assertLess(mean(first, "RandIndexError"), 0.12)
        self.assertLess(max(float(r["Fidelity"]) for r in first), 0.2)
        for rows in (grown, refined):
            self.assertLess(mean(rows, "Fidelity"), 0.022)
            self.assertLess(mean(rows, "RandIndexError"), 0.12)
            self.assertLess(max(float(r["Fidelity"]) for r in rows), 0.06)
        self.assertGreater(mean(refined, "InputSegmentsMatched"), 0.95)
        # Each run has a stroke per segment at least, and the corrections add more.
        for a, b in zip(sorted(first, key=lambda r: r["Model"]), sorted(refined, key=lambda r: r["Model"])):
            self.assertGreaterEqual(float(a["Inputs"]), 1)
            self.assertGreater(float(b["Inputs"]), float(a["Inputs"]) - 1e-9)
        # Boundary editing (section 5.2): one round of override strokes along the input human's
        # boundaries where faces are still wrong takes the snakes' 0.020 to 0.0098 (worst model
        # 0.036, a bearing) with 7.4 more strokes per run on average; a round adds no stroke where
        # nothing is wrong, so the inputs never fall.
        edited = run("region-growing+snakes", "overrides=1")
        self.assertLess(mean(edited, "Fidelity"), 0.011)
        self.assertLess(max(float(r["Fidelity"]) for r in edited), 0.04)
        self.assertLess(mean(edited, "RandIndexError"), mean(refined, "RandIndexError"))
        self.assertGreater(mean(edited, "Inputs"), mean(refined, "Inputs") + 5)
        for a, b in zip(sorted(refined, key=lambda r: r["Model"]), sorted(edited, key=lambda r: r["Model"])):
            self.assertGreaterEqual(float(b["Inputs"]), float(a["Inputs"]))
        # The aim, the harmonic cuts' fidelity under 0.01: six rounds of corrections, then one of
        # overrides, on the grown labels (the snakes smooth the boundary away from the humans' face
        # boundaries): 0.0066 (worst model 0.022, a fourleg), for 50.9 strokes per run on average.
        aimed = run("region-growing", "corrections=6;overrides=1")
        self.assertLess(mean(aimed, "Fidelity"), 0.0075)
        self.assertLess(max(float(r["Fidelity"]) for r in aimed), 0.03)
        self.assertLess(mean(aimed, "RandIndexError"), mean(edited, "RandIndexError"))
        self.assertLess(mean(aimed, "Inputs"), 55)

    def test_the_ensemble_beats_every_method(self):
        # Automatic segmentation with k from nSeg-ByModel.txt, scored against every human of each
        # model. The issue: the flagship below 0.20 and below every survey family, the goal 0.15.
        # Measured mean 1 - Rand index: the ensemble 0.1319 (0.1437 without the boundary band;
        # asserted below 0.14 and below its own linkage's boundaries), consensus
        # cuts 0.1755 (0.191 without the random walks; asserted below 0.185 so that the walks' gain
        # stays), spectral 0.215, k-means 0.275, convex flooding 0.295, face clustering 0.349,
        # watershed 0.598 (the humans among themselves: 0.111); core extraction 0.2022 with its own k.
        def mean_rand_index(method, parameters=""):
            out = os.path.join(self.folder, "automatic-" + method + parameters.replace("=", "-"))
            result = subprocess.run([PROGRAM, "benchmark", "--data", DATA, "--method", method, "--parameters",
                                     parameters, "--jobs", "2", "--no-pictures", "-o", out],
                                    capture_output=True, text=True, timeout=1200)
            self.assertEqual(result.returncode, 0, result.stderr)
            rows = read_rows(os.path.join(out, "results.csv"))
            self.assertEqual(len(rows), len(readme_human_rand_index()), method)
            return sum(float(r["RandIndexError"]) for r in rows) / len(rows)

        flagship = mean_rand_index("ensemble")
        self.assertLess(flagship, 0.14)
        self.assertLess(flagship, mean_rand_index("ensemble", "band=0") - 0.005)
        cuts = mean_rand_index("consensus-cuts")
        self.assertLess(cuts, 0.185)
        self.assertLess(flagship, cuts)
        families = {}
        for family in ("spectral", "k-means", "convex-flooding", "face-clustering", "watershed"):
            families[family] = mean_rand_index(family)
            self.assertLess(cuts, families[family], family)
        # Core extraction, with the number of segments its own (k unread): measured 0.2022, below
        # every survey family, which are given the humans' k.
        core = mean_rand_index("core-extraction")
        self.assertLess(core, 0.21)
        for family, mean in families.items():
            self.assertLess(core, mean, family)

    def test_harmonic_cuts_from_simulated_strokes(self):
        out = os.path.join(self.folder, "harmonic")
        result = subprocess.run([PROGRAM, "benchmark", "--data", DATA, "--method", "harmonic-cuts",
                                 "--jobs", "2", "--no-pictures", "-o", out],
                                capture_output=True, text=True, timeout=1200)
        self.assertEqual(result.returncode, 0, result.stderr)
        rows = {int(r["Model"]): r for r in read_rows(os.path.join(out, "results.csv"))}
        humans = readme_human_rand_index()
        self.assertEqual(sorted(rows), sorted(humans))
        # Over psb-dev, every human in turn as the input: mean fidelity 0.0021 (the goal: at most
        # 0.003), the worst model 0.0069 (the goal: none above 0.01; a bird, 243, whose human 12
        # drew segments of 1 to 49 faces, stays at 0.0024 because a short stroke's constraint
        # offset is at most 5% of its length), the input's number of segments reproduced in 99.0%
        # of the runs (the goal: 95%).
        fidelities = [float(r["Fidelity"]) for r in rows.values()]
        self.assertLessEqual(sum(fidelities) / len(fidelities), 0.003)
        self.assertLess(max(fidelities), 0.01)
        self.assertLess(float(rows[243]["Fidelity"]), 0.005)
        matched = [float(r["InputSegmentsMatched"]) for r in rows.values()]
        self.assertGreaterEqual(sum(matched) / len(matched), 0.95)
        for model in (36, 125, 342):
            row = rows[model]
            segs = len([f for f in os.listdir(os.path.join(DATA, "seg", str(model))) if f.endswith(".seg")])
            # Every human in turn gives the strokes; each result is scored against the others.
            self.assertEqual(int(row["Comparisons"]), segs * (segs - 1))
            self.assertEqual(row["Method"], "harmonic-cuts")
            self.assertGreater(float(row["Seconds"]), 0.0)
            self.assertGreaterEqual(float(row["Segments"]), 2)
            self.assertGreaterEqual(float(row["Inputs"]), 1)
            # The strokes' intent is reproduced on these: against the input human, 1 - Rand index
            # under 0.01 (psb-dev's humans agree to 0.11 on average)...
            self.assertLess(float(row["Fidelity"]), 0.01, "model %d" % model)
            self.assertLess(float(row["FidelityHamming"]), 0.02, "model %d" % model)
            # ...and a segmentation about as close to the other humans as they are to each other.
            self.assertLess(float(row["RandIndexError"]), humans[model] + 0.05, "model %d" % model)
        summary = {r["Category"]: r for r in read_rows(os.path.join(out, "summary.csv"))}
        self.assertAlmostEqual(float(summary["all"]["Fidelity"]), sum(fidelities) / len(fidelities), places=9)
        bad = subprocess.run([PROGRAM, "benchmark", "--data", DATA, "--method", "harmonic-cuts",
                              "--models", "36", "--parameters", "weighting=magic", "--no-pictures",
                              "-o", os.path.join(self.folder, "bad")], capture_output=True, text=True, timeout=120)
        self.assertEqual(bad.returncode, 1)
        self.assertIn("weighting must be", bad.stderr)
        # The formulation is a parameter: on glasses 52 (3,104 triangles, the stroke offset half an
        # edge) point values reproduce the input worse than least squares (measured 0.045 against
        # 0.0038 on average over its humans).
        coarse = {}
        for formulation in ("least-squares", "point-values"):
            folder = os.path.join(self.folder, "formulation-" + formulation)
            run = subprocess.run([PROGRAM, "benchmark", "--data", DATA, "--method", "harmonic-cuts", "--models", "52",
                                  "--parameters", "formulation=" + formulation, "--no-pictures", "-o", folder],
                                 capture_output=True, text=True, timeout=300)
            self.assertEqual(run.returncode, 0, run.stderr)
            coarse[formulation] = float(read_rows(os.path.join(folder, "results.csv"))[0]["Fidelity"])
        self.assertAlmostEqual(coarse["least-squares"], float(rows[52]["Fidelity"]), places=12)
        self.assertGreater(coarse["point-values"], 5 * coarse["least-squares"])
        wrong = subprocess.run([PROGRAM, "benchmark", "--data", DATA, "--method", "harmonic-cuts", "--models", "52",
                                "--parameters", "formulation=exact", "--no-pictures",
                                "-o", os.path.join(self.folder, "bad")], capture_output=True, text=True, timeout=120)
        self.assertEqual(wrong.returncode, 1)
        self.assertIn("formulation must be least-squares or point-values", wrong.stderr)

    def test_errors_are_reported(self):
        for arguments, message in (
                (["--data", "/nonexistent/psb"], "no off/ subfolder"),
                (["--data", DATA, "--method", "nonsense", "--models", "1"], "unknown method 'nonsense'"),
                (["--data", DATA, "--models", "12345"], "model 12345 is not in"),
                (["--data", DATA, "--jobs", "0"], "--jobs expects"),
                (["--data", DATA, "--method", "region-growing", "--models", "1", "--parameters",
                  "placement=fronts;cut-band=0.3"], "applies to placement=minimum-cut and random-walks only"),
                # Parameters are separated by semicolons: a number followed by more text is refused,
                # not read as its leading number.
                (["--data", DATA, "--method", "consensus-cuts", "--models", "125", "--parameters",
                  "length=0.75,sizes=0.5"], "method parameter length must be a number, got '0.75,sizes=0.5'"),
                (["--data", DATA, "--method", "consensus-cuts", "--models", "125", "--parameters",
                  "clip=-0.1"], "method parameter clip must be a positive number, got '-0.1'")):
            for command in ([PROGRAM, "benchmark"], [sys.executable, "-m", "kerf.benchmark"]):
                result = subprocess.run(command + arguments + ["--no-pictures", "-o", os.path.join(self.folder, "bad")],
                                        capture_output=True, text=True, timeout=120)
                self.assertEqual(result.returncode, 1, command + arguments)
                self.assertIn(message, result.stderr, command + arguments)
                self.assertNotIn("ERROR:", result.stderr)


if __name__ == "__main__":
    if not os.path.isdir(os.path.join(DATA, "off")):
        print("../shared/data/psb-dev is absent: skipped")
        sys.exit(125)
    unittest.main(argv=[sys.argv[0]])
