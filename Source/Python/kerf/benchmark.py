"""Benchmark runner: the Python equivalent of `kerf benchmark`.

Runs a Kerf segmentation method over a folder in the Princeton Segmentation Benchmark's layout
(off/N.off, seg/N/N_j.seg, nSeg-ByModel.txt), scores it against the human segmentations with
vtkSegmentationBenchmark, and writes results.csv, summary.csv and pictures/N.png (the method's
segmentation beside a human's), exactly as the command-line program does::

    python3 -m kerf.benchmark --data ../shared/data/psb-dev --method human --jobs 2 -o out

Rendering needs a display: run it under `xvfb-run -a` on a headless machine, or pass
--no-pictures.
"""

import argparse
import csv
import multiprocessing
import os
import sys
import time

RESULT_COLUMNS = ["Comparisons", "CutDiscrepancy", "HammingDistance", "MissingRate",
                  "FalseAlarmRate", "RandIndexError", "GlobalConsistencyError",
                  "LocalConsistencyError", "Segments", "Seconds"]
SUMMARY_METRICS = ["CutDiscrepancy", "HammingDistance", "RandIndexError",
                   "GlobalConsistencyError", "LocalConsistencyError", "Seconds"]
LABEL_COLORS = [(0.122, 0.467, 0.706), (1.000, 0.498, 0.055), (0.173, 0.627, 0.173),
                (0.839, 0.153, 0.157), (0.580, 0.404, 0.741), (0.549, 0.337, 0.294),
                (0.890, 0.467, 0.761), (0.498, 0.498, 0.498), (0.737, 0.741, 0.133),
                (0.090, 0.745, 0.812), (0.682, 0.780, 0.910), (1.000, 0.733, 0.471)]


class BenchmarkError(Exception):
    """A failure reported as `kerf.benchmark: error: ...` with exit code 1."""


def _run(algorithm, what):
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


def _picture(surface, model, method, file_name):
    """Renders the method's segmentation beside a human's, coloured alike, into a PNG."""
    from vtkmodules.vtkCommonCore import vtkLookupTable
    from vtkmodules.vtkIOImage import vtkPNGWriter
    from vtkmodules.vtkRenderingCore import (vtkActor, vtkPolyDataMapper, vtkRenderWindow,
                                             vtkRenderer, vtkTextActor, vtkWindowToImageFilter)
    import vtkmodules.vtkRenderingOpenGL2  # noqa: F401 (rendering back end)
    import vtkmodules.vtkRenderingFreeType  # noqa: F401 (text)

    labels = [surface.GetCellData().GetArray(name).GetRange() for name in ("Method", "Human")]
    top = int(max(high for _, high in labels))
    table = vtkLookupTable()
    table.SetNumberOfTableValues(top + 1)
    for i in range(top + 1):
        table.SetTableValue(i, *LABEL_COLORS[i % len(LABEL_COLORS)], 1.0)
    table.SetTableRange(-0.5, top + 0.5)
    table.Build()
    window = vtkRenderWindow()
    window.SetOffScreenRendering(1)
    window.SetSize(1000, 520)
    camera = None
    for index, (array, caption) in enumerate(
            [("Method", "model %d: %s" % (model, method)),
             ("Human", "another human" if method == "human" else "a human")]):
        mapper = vtkPolyDataMapper()
        mapper.SetInputData(surface)
        mapper.SetLookupTable(table)
        mapper.SetScalarModeToUseCellFieldData()
        mapper.SelectColorArray(array)
        mapper.SetUseLookupTableScalarRange(True)
        actor = vtkActor()
        actor.SetMapper(mapper)
        renderer = vtkRenderer()
        renderer.SetViewport(0.5 * index, 0.0, 0.5 * index + 0.5, 1.0)
        renderer.GradientBackgroundOn()
        renderer.SetBackground(0.93, 0.93, 0.95)
        renderer.SetBackground2(0.72, 0.75, 0.82)
        renderer.AddActor(actor)
        text = vtkTextActor()
        text.SetInput(caption)
        text.GetTextProperty().SetFontSize(16)
        text.GetTextProperty().SetColor(0.1, 0.1, 0.1)
        text.SetDisplayPosition(12 + 500 * index, 490)
        renderer.AddActor2D(text)
        if camera is None:
            renderer.ResetCamera()
            camera = renderer.GetActiveCamera()
            bounds = surface.GetBounds()
            extent = [bounds[1] - bounds[0], bounds[3] - bounds[2], bounds[5] - bounds[4]]
            shortest, longest = extent.index(min(extent)), extent.index(max(extent))
            focal = camera.GetFocalPoint()
            position = list(focal)
            position[shortest] += camera.GetDistance()
            up = [0.0, 0.0, 0.0]
            up[longest if longest != shortest else (shortest + 1) % 3] = 1.0
            camera.SetPosition(position)
            camera.SetViewUp(up)
            camera.Azimuth(20.0)
            camera.Elevation(15.0)
            camera.OrthogonalizeViewUp()
            renderer.ResetCamera()
        else:
            renderer.SetActiveCamera(camera)
        window.AddRenderer(renderer)
    window.Render()
    grab = vtkWindowToImageFilter()
    grab.SetInput(window)
    grab.ReadFrontBufferOff()
    writer = vtkPNGWriter()
    writer.SetFileName(file_name)
    writer.SetInputConnection(grab.GetOutputPort())
    writer.Write()


def run_model(data, method, parameters, model, pictures):
    """Runs the method on one model (in a worker process); returns its results.csv row."""
    import kerf
    started = time.perf_counter()
    benchmark = kerf.vtkSegmentationBenchmark()
    benchmark.SetDataDirectory(data)
    benchmark.SetMethod(method)
    benchmark.SetMethodParameters(parameters)
    benchmark.AddModel(model)
    _run(benchmark, "model %d" % model)
    table = benchmark.GetOutput()
    row = {"Model": model, "Category": table.GetValueByName(0, "Category").ToString(),
           "Method": method, "Parameters": parameters}
    for column in RESULT_COLUMNS:
        row[column] = table.GetValueByName(0, column).ToDouble()
    if pictures:
        _picture(benchmark.GetOutputDataObject(1), model, method,
                 os.path.join(pictures, "%d.png" % model))
    row["_wall"] = time.perf_counter() - started
    return row


def _work(arguments):
    try:
        return run_model(*arguments)
    except BenchmarkError as error:
        return {"error": str(error)}


def summarize(rows):
    """Per-category means of the summary metrics, categories sorted, then 'all'."""
    groups = {}
    for row in rows:
        groups.setdefault(row["Category"], []).append(row)
    ordered = [(name, groups[name]) for name in sorted(groups)] + [("all", rows)]
    return [(name, len(members),
             [sum(r[m] for r in members) / len(members) for m in SUMMARY_METRICS])
            for name, members in ordered]


def main(argv=None):
    parser = argparse.ArgumentParser(prog="python3 -m kerf.benchmark", description=__doc__.split("\n\n")[0])
    parser.add_argument("--data", required=True, help="folder in the benchmark's layout")
    parser.add_argument("--method", default="human", help="method to evaluate (default: human)")
    parser.add_argument("--parameters", default="", help="the method's parameters, name=value;...")
    parser.add_argument("--models", default="", help="ids separated by commas (default: all)")
    parser.add_argument("--jobs", type=int, default=1, help="worker processes (default: 1)")
    parser.add_argument("-o", "--output", default="kerf-benchmark", help="output folder")
    parser.add_argument("--no-pictures", action="store_true", help="skip the pictures")
    args = parser.parse_args(argv)
    try:
        import kerf
        if args.jobs < 1 or args.jobs > 64:
            raise BenchmarkError("--jobs expects a whole number from 1 to 64")
        if args.models:
            try:
                models = [int(item) for item in args.models.split(",")]
            except ValueError:
                raise BenchmarkError("--models expects ids separated by commas, got '%s'" % args.models)
        else:
            from vtkmodules.vtkCommonCore import reference
            error = reference("")
            models = list(kerf.vtkSegmentationBenchmark.FindModels(args.data, error))
            if not models:
                raise BenchmarkError(str(error) or "%s holds no models" % args.data)
        pictures = "" if args.no_pictures else os.path.join(args.output, "pictures")
        os.makedirs(pictures or args.output, exist_ok=True)
        print("Kerf benchmark: method %s on %d models of %s with %d process%s"
              % (args.method, len(models), args.data, args.jobs, "" if args.jobs == 1 else "es"))
        started = time.perf_counter()
        work = [(args.data, args.method, args.parameters, m, pictures) for m in models]
        rows = []
        with multiprocessing.get_context("fork").Pool(args.jobs) as pool:
            for row in pool.imap_unordered(_work, work):
                if "error" in row:
                    raise BenchmarkError(row["error"])
                rows.append(row)
                print("[%3d/%d] model %4d %-10s 1-RI %.3f  CD %.3f  HD %.3f  (%.2f s)"
                      % (len(rows), len(models), row["Model"], row["Category"],
                         row["RandIndexError"], row["CutDiscrepancy"], row["HammingDistance"],
                         row["Seconds"]), flush=True)
        rows.sort(key=lambda r: r["Model"])
        results = os.path.join(args.output, "results.csv")
        with open(results, "w") as f:
            f.write(",".join(["Model", "Category", "Method", "Parameters"] + RESULT_COLUMNS) + "\n")
            for r in rows:
                quoted = '"%s"' % r["Parameters"].replace('"', '""')
                f.write(",".join([str(r["Model"]), r["Category"], r["Method"], quoted]
                                 + ["%.10g" % r[c] for c in RESULT_COLUMNS]) + "\n")
        summary = os.path.join(args.output, "summary.csv")
        print("\n%-11s%7s%9s%9s%9s%9s%9s%10s" % ("category", "models", "CD", "HD", "1-RI", "GCE", "LCE", "seconds"))
        with open(summary, "w", newline="") as f:
            out = csv.writer(f, lineterminator="\n")
            out.writerow(["Category", "Method", "Models"] + SUMMARY_METRICS)
            for name, count, means in summarize(rows):
                out.writerow([name, args.method, count] + ["%.10g" % m for m in means])
                print("%-11s%7d" % (name, count) + "".join("%9.3f" % m for m in means[:-1])
                      + "%10.3f" % means[-1])
        print("\nresults:  %s\nsummary:  %s" % (os.path.abspath(results), os.path.abspath(summary)))
        if pictures:
            print("pictures: %s" % os.path.abspath(pictures))
        print("time:     %.1f s" % (time.perf_counter() - started))
        return 0
    except BenchmarkError as error:
        print("kerf.benchmark: error: %s" % error, file=sys.stderr)
        return 1


if __name__ == "__main__":
    sys.exit(main())
