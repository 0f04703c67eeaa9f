"""Benchmark runner: the Python front end of `kerf benchmark`.

Runs a Kerf segmentation method over a folder in the Princeton Segmentation Benchmark's layout
(off/N.off, seg/N/N_j.seg, nSeg-ByModel.txt), scores it against the human segmentations and
writes results.csv, summary.csv and pictures/N.png (the method's segmentation beside a human's),
exactly as the command-line program does: both call the same runner, vtkSegmentationBenchmark::

    python3 -m kerf.benchmark --data ../shared/data/psb-dev --method human --jobs 2 -o out

Rendering needs a display: run it under `xvfb-run -a` on a headless machine, or pass
--no-pictures.
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


def parse_models(text):
    try:
        return [int(item) for item in text.split(",")]
    except ValueError:
        raise BenchmarkError("--models expects ids separated by commas, got '%s'" % text)


def main(argv=None):
    import kerf
    methods = "\n".join("  %-23s%s" % (name, kerf.vtkSegmentationBenchmark.GetMethodDescription(name))
                        for name in kerf.vtkSegmentationBenchmark.GetMethodNames())
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
        benchmark.SetOutputDirectory(args.output)
        benchmark.SetWritePictures(not args.no_pictures)
        if not args.no_pictures:
            import vtkmodules.vtkRenderingOpenGL2  # noqa: F401 (the pictures' rendering back end)
            import vtkmodules.vtkRenderingFreeType  # noqa: F401 (their captions)
        benchmark.PrintProgressOn()
        print("Kerf benchmark: method %s on %d models of %s with %d process%s"
              % (args.method, len(models), args.data, args.jobs, "" if args.jobs == 1 else "es"), flush=True)
        started = time.perf_counter()
        run(benchmark, "benchmark")
        print("\n" + benchmark.GetSummary(), end="")
        print("\nresults:  %s\nsummary:  %s" % (os.path.abspath(os.path.join(args.output, "results.csv")),
                                                os.path.abspath(os.path.join(args.output, "summary.csv"))))
        if not args.no_pictures:
            print("pictures: %s" % os.path.abspath(os.path.join(args.output, "pictures")))
        print("time:     %.1f s" % (time.perf_counter() - started))
        return 0
    except BenchmarkError as error:
        print("kerf.benchmark: error: %s" % error, file=sys.stderr)
        return 1


if __name__ == "__main__":
    sys.exit(main())
