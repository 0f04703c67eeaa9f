"""The benchmark runner on 2 MPI ranks (pvbatch --symmetric under mpirun): the models are spread
over the ranks, rank 0 gathers them and writes the same results.csv and summary.csv, byte for
byte, as the serial runner (their Seconds column aside, which is measured)."""
import csv
import os
import subprocess
import sys

sys.path.insert(0, os.environ["KERF_PYTHON_PATH"])
from vtkmodules.vtkParallelCore import vtkMultiProcessController  # noqa: E402

import kerf.benchmark  # noqa: E402

DATA = os.path.join(os.environ["KERF_SHARED_DATA"], "psb-dev")
MODELS = "9,36,125,142,342"


def rows_without_time(path):
    with open(path) as f:
        rows = list(csv.DictReader(f))
    for row in rows:
        row.pop("Seconds")
    return rows


controller = vtkMultiProcessController.GetGlobalController()
rank = controller.GetLocalProcessId()
if not os.path.isdir(os.path.join(DATA, "off")):
    if rank == 0:
        print("../shared/data/psb-dev is absent: skipped")
    sys.exit(125)
assert controller.GetNumberOfProcesses() == 2, "run with mpirun -np 2 pvbatch --symmetric"
out = os.path.join(os.environ["KERF_TEST_OUTPUT"], "batch-mpi")
status = kerf.benchmark.main(["--data", DATA, "--method", "harmonic-cuts", "--models", MODELS,
                              "--no-pictures", "-o", os.path.join(out, "mpi")])
assert status == 0
if rank == 0:
    serial = subprocess.run(["/usr/bin/python3", "-m", "kerf.benchmark", "--data", DATA, "--method", "harmonic-cuts",
                             "--models", MODELS, "--no-pictures", "-o", os.path.join(out, "serial")],
                            capture_output=True, text=True, timeout=600)
    assert serial.returncode == 0, serial.stderr
    mpi_rows = rows_without_time(os.path.join(out, "mpi", "results.csv"))
    serial_rows = rows_without_time(os.path.join(out, "serial", "results.csv"))
    assert [r["Model"] for r in mpi_rows] == MODELS.split(",") or \
        sorted(int(r["Model"]) for r in mpi_rows) == sorted(int(m) for m in MODELS.split(",")), mpi_rows
    assert mpi_rows == serial_rows, (mpi_rows, serial_rows)
    print("2 ranks: %d models, the same results as the serial runner" % len(mpi_rows))
