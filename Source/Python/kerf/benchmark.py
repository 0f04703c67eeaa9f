"""Benchmark runner: the Python front end of `kerf benchmark`.

Runs a Kerf segmentation method over a folder in the Princeton Segmentation Benchmark's layout
(off/N.off, seg/N/N_j.seg, nSeg-ByModel.txt), scores it against the human segmentations and
writes results.csv, summary.csv and pictures/N.png (the method's segmentation beside a human's),
exactly as the command-line program does: both call the same runner, vtkSegmentationBenchmark::

    python3 -m kerf.benchmark --data ../shared/data/psb-dev --method human --jobs 2 -o out

Rendering needs a display: run it under `xvfb-run -a` on a headless machine, or pass
--no-pictures.

On many machines, the same runner under ParaView's MPI build spreads the models over the ranks
and gathers the results on rank 0, which writes the same results.csv and summary.csv as a
serial run::

    mpirun -np 4 pvbatch --symmetric -- "$(python3 -c 'import kerf.benchmark as b; print(b.__file__)')" \
        --data ../shared/data/psb-dev --method harmonic-cuts --no-pictures -o out

(with the build's kerf package on PYTHONPATH and its libraries on LD_LIBRARY_PATH).
"""

import argparse
import os
import sys
import time


class BenchmarkError(Exception):
    """A failure reported as `kerf.benchmark: error: ...` with exit code 1."""


def run(algorithm, what):
    """Updates a VTK algorithm and raises BenchmarkError with its error message on failure."""
    from vtkmodules.util.misc import calldata_type
    from vtkmodules.util.vtkConstants import VTK_STRING
    from vtkmodules.vtkCommonCore import vtkCommand
    messages = []

    @calldata_type(VTK_STRING)
    def collect(caller, event, data):
        messages.append(str(data).split("): ", 1)[-1].strip())
    algorithm.AddObserver(vtkCommand.ErrorEvent, collect)
    algorithm.GetExecutive().AddObserver(vtkCommand.ErrorEvent, collect)
    if not algorithm.GetExecutive().Update() or messages:
        raise BenchmarkError("%s: %s" % (what, messages[0] if messages else "failed"))


def mpi_controller():
    """The MPI controller when running on several ranks (pvbatch --symmetric under mpirun), else None."""
    try:
        from vtkmodules.vtkParallelCore import vtkMultiProcessController
    except ImportError:
        return None
    controller = vtkMultiProcessController.GetGlobalController()
    if controller is None or controller.GetNumberOfProcesses() < 2:
        return None
    return controller


def gather_tables(controller, table):
    """Rank 0 receives every rank's table and returns them all appended; the others return None."""
    from vtkmodules.vtkCommonDataModel import vtkTable
    tag = 8031
    if controller.GetLocalProcessId() != 0:
        controller.Send(table, 0, tag)
        return None
    parts = [table]
    for rank in range(1, controller.GetNumberOfProcesses()):
        part = vtkTable()
        controller.Receive(part, rank, tag)
        parts.append(part)
    whole = vtkTable()
    for part in parts:
        if part.GetNumberOfColumns() == 0:
            continue  # a rank with no model
        if whole.GetNumberOfColumns() == 0:
            whole.DeepCopy(part)
            continue
        for row in range(part.GetNumberOfRows()):
            whole.InsertNextRow(part.GetRow(row))
    return whole


def parse_models(text):
    try:
        return [int(item) for item in text.split(",")]
    except ValueError:
        raise BenchmarkError("--models expects ids separated by commas, got '%s'" % text)


def main(argv=None):
    import kerf
    names = list(kerf.vtkSegmentationBenchmark.GetMethodNames())
    width = max(len(name) for name in names) + 2
    methods = "\n".join("  %-*s%s" % (width, name, kerf.vtkSegmentationBenchmark.GetMethodDescription(name))
                        for name in names)
    parser = argparse.ArgumentParser(prog="python3 -m kerf.benchmark", description=__doc__.split("\n\n")[0],
                                     epilog="methods:\n" + methods,
                                     formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("--data", required=True, help="folder in the benchmark's layout")
    parser.add_argument("--method", default="human", help="method to evaluate (default: human)")
    parser.add_argument("--parameters", default="", help="the method's parameters, name=value;...")
    parser.add_argument("--models", default="", help="ids separated by commas (default: all)")
    parser.add_argument("--jobs", type=int, default=1, help="worker processes (default: 1)")
    parser.add_argument("-o", "--output", default="kerf-benchmark", help="output folder")
    parser.add_argument("--no-pictures", action="store_true", help="skip the pictures")
    args = parser.parse_args(argv)
    try:
        if args.jobs < 1 or args.jobs > 64:
            raise BenchmarkError("--jobs expects a whole number from 1 to 64")
        benchmark = kerf.vtkSegmentationBenchmark()
        benchmark.SetDataDirectory(args.data)
        benchmark.SetMethod(args.method)
        benchmark.SetMethodParameters(args.parameters)
        benchmark.SetNumberOfJobs(args.jobs)
        if args.models:
            models = parse_models(args.models)
        else:
            from vtkmodules.vtkCommonCore import reference
            error = reference("")
            models = list(kerf.vtkSegmentationBenchmark.FindModels(args.data, error))
            if not models:
                raise BenchmarkError(str(error) or "%s holds no models" % args.data)
        for model in models if args.models else []:
            benchmark.AddModel(model)
        controller = mpi_controller()
        rank = controller.GetLocalProcessId() if controller else 0
        ranks = controller.GetNumberOfProcesses() if controller else 1
        if controller:
            # Every rank runs its share of the models; rank 0 writes the files of them all.
            mine = models[rank::ranks]
            benchmark.ClearModels()
            for model in mine:
                benchmark.AddModel(model)
            if not args.no_pictures:
                benchmark.SetOutputDirectory(os.path.join(args.output, "rank-%d" % rank))
        else:
            benchmark.SetOutputDirectory(args.output)
        benchmark.SetWritePictures(not args.no_pictures)
        if not args.no_pictures:
            import vtkmodules.vtkRenderingOpenGL2  # noqa: F401 (the pictures' rendering back end)
            import vtkmodules.vtkRenderingFreeType  # noqa: F401 (their captions)
        benchmark.PrintProgressOn()
        if rank == 0:
            print("Kerf benchmark: method %s on %d models of %s with %d %s"
                  % (args.method, len(models), args.data, ranks if controller else args.jobs,
                     ("MPI ranks" if controller else "process" if args.jobs == 1 else "processes")), flush=True)
        started = time.perf_counter()
        if not controller or mine:
            run(benchmark, "benchmark")
        if controller:
            from vtkmodules.vtkCommonDataModel import vtkTable
            table = benchmark.GetOutput() if mine else vtkTable()
            whole = gather_tables(controller, table)
            if rank != 0:
                return 0
            from vtkmodules.vtkCommonCore import reference
            error = reference("")
            summary = kerf.vtkSegmentationBenchmark.WriteResults(whole, args.output, error)
            if not summary:
                raise BenchmarkError(str(error))
        else:
            summary = benchmark.GetSummary()
        print("\n" + summary, end="")
        print("\nresults:  %s\nsummary:  %s" % (os.path.abspath(os.path.join(args.output, "results.csv")),
                                                os.path.abspath(os.path.join(args.output, "summary.csv"))))
        if not args.no_pictures:
            print("pictures: %s" % os.path.abspath(os.path.join(args.output, "rank-*" if controller else "pictures")))
        print("time:     %.1f s" % (time.perf_counter() - started))
        return 0
    except BenchmarkError as error:
        print("kerf.benchmark: error: %s" % error, file=sys.stderr)
        return 1


if __name__ == "__main__":
    sys.exit(main())
