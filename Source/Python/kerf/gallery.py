"""Gallery: segmentation methods side by side on one model per category of a benchmark folder.

Runs each method on the first model of every category (every block of 20 model ids, the
Princeton benchmark's categories) of a folder in the benchmark's layout, with k from
nSeg-ByModel.txt, through the benchmark runner (vtkSegmentationBenchmark, so the methods and
their parameters are those of `kerf benchmark`), and draws one picture: a row per model, a
column per method, and a first column with the human segmentation the methods' colours are
matched to::

    xvfb-run -a python3 -m kerf.gallery --data ../shared/data/psb-dev \\
        --methods ensemble,consensus-cuts,face-clustering,watershed,k-means -o gallery.png

Prints, per model and method, the number of segments and 1 - Rand index against the shown
human. Rendering needs a display (xvfb-run -a on a headless machine).
"""

import argparse
import sys

from kerf.benchmark import BenchmarkError, run

CELL = 260  # pixels per picture of one model by one method
HEADER = 28  # pixels above the columns and left of the rows for their names
CATEGORY_SIZE = 20  # model ids per category in the Princeton benchmark


def first_model_per_category(models):
    """The smallest model id of each block of CATEGORY_SIZE ids, in order."""
    chosen = {}
    for model in sorted(models):
        chosen.setdefault((model - 1) // CATEGORY_SIZE, model)
    return [chosen[block] for block in sorted(chosen)]


def segment(data, method, parameters, model):
    """The model's mesh with the cell arrays Method and Human, and its row of the runner's table."""
    import kerf
    benchmark = kerf.vtkSegmentationBenchmark()
    benchmark.SetDataDirectory(data)
    benchmark.SetMethod(method)
    benchmark.SetMethodParameters(parameters.get(method, ""))
    benchmark.AddModel(model)
    run(benchmark, "%s on model %d" % (method, model))
    table = benchmark.GetOutput(0)
    row = {table.GetColumnName(c): table.GetValue(0, c).ToString() for c in range(table.GetNumberOfColumns())}
    from vtkmodules.vtkCommonDataModel import vtkPolyData
    mesh = vtkPolyData()
    mesh.DeepCopy(benchmark.GetOutputDataObject(1))
    return mesh, row


def camera_for(renderer, mesh):
    """Looks along the bounding box's shortest axis with its longest axis up."""
    bounds = mesh.GetBounds()
    sizes = [bounds[2 * a + 1] - bounds[2 * a] for a in range(3)]
    order = sorted(range(3), key=lambda a: (sizes[a], a))
    shortest, longest = order[0], order[2]
    centre = [(bounds[2 * a] + bounds[2 * a + 1]) / 2.0 for a in range(3)]
    camera = renderer.GetActiveCamera()
    camera.SetFocalPoint(centre)
    position = list(centre)
    position[shortest] += 1.0
    camera.SetPosition(position)
    up = [0.0, 0.0, 0.0]
    up[longest] = 1.0
    camera.SetViewUp(up)
    renderer.ResetCamera()
    camera.Azimuth(20.0)
    camera.Elevation(15.0)
    camera.Zoom(1.05)


def coloured(mesh, array):
    """A shallow copy of `mesh` whose cells carry the colour of their label in `array` (a
    qualitative palette, label i colour i modulo its size) as direct RGB scalars."""
    from vtkmodules.vtkCommonColor import vtkColorSeries
    from vtkmodules.vtkCommonCore import vtkUnsignedCharArray
    from vtkmodules.vtkCommonDataModel import vtkPolyData
    series = vtkColorSeries()
    series.SetColorScheme(vtkColorSeries.BREWER_QUALITATIVE_SET3)
    palette = [series.GetColor(i) for i in range(series.GetNumberOfColors())]
    labels = mesh.GetCellData().GetArray(array)
    colours = vtkUnsignedCharArray()
    colours.SetName("Colour")
    colours.SetNumberOfComponents(3)
    colours.SetNumberOfTuples(labels.GetNumberOfTuples())
    for cell in range(labels.GetNumberOfTuples()):
        colour = palette[int(labels.GetValue(cell)) % len(palette)]
        colours.SetTuple3(cell, colour.GetRed(), colour.GetGreen(), colour.GetBlue())
    copy = vtkPolyData()
    copy.ShallowCopy(mesh)
    copy.GetCellData().SetScalars(colours)
    return copy


def add_label(renderer, name, x, y, orientation):
    """A dark 16-point label centred at pixel (x, y), turned by `orientation` degrees."""
    from vtkmodules.vtkRenderingCore import vtkActor2D, vtkTextMapper
    text = vtkTextMapper()
    text.SetInput(name)
    text.GetTextProperty().SetFontSize(16)
    text.GetTextProperty().SetColor(0.1, 0.1, 0.1)
    text.GetTextProperty().SetOrientation(orientation)
    text.GetTextProperty().SetJustificationToCentered()
    label = vtkActor2D()
    label.SetMapper(text)
    label.SetPosition(x, y)
    renderer.AddActor2D(label)


def draw(rows, columns, pictures, path):
    """Draws pictures[r][c] = (mesh, array name) in a grid with the row and column names."""
    from vtkmodules.vtkIOImage import vtkPNGWriter
    from vtkmodules.vtkRenderingCore import (vtkActor, vtkPolyDataMapper, vtkRenderer, vtkRenderWindow,
                                             vtkWindowToImageFilter)
    import vtkmodules.vtkRenderingOpenGL2  # noqa: F401 (the rendering back end)
    import vtkmodules.vtkRenderingFreeType  # noqa: F401 (text)
    width = HEADER + CELL * len(columns)
    height = HEADER + CELL * len(rows)
    window = vtkRenderWindow()
    window.SetOffScreenRendering(True)
    window.SetSize(width, height)
    window.SetMultiSamples(0)
    background = vtkRenderer()
    background.SetBackground(1.0, 1.0, 1.0)
    background.SetViewport(0.0, 0.0, 1.0, 1.0)
    window.AddRenderer(background)
    for r in range(len(rows)):
        for c in range(len(columns)):
            mesh, array = pictures[r][c]
            mapper = vtkPolyDataMapper()
            mapper.SetInputData(coloured(mesh, array))
            mapper.SetScalarModeToUseCellData()
            mapper.SetColorModeToDirectScalars()
            actor = vtkActor()
            actor.SetMapper(mapper)
            renderer = vtkRenderer()
            renderer.SetBackground(0.97, 0.97, 0.97)
            x0 = (HEADER + c * CELL + 1) / width
            y1 = 1.0 - (HEADER + r * CELL + 1) / height
            renderer.SetViewport(x0, y1 - (CELL - 2) / height, x0 + (CELL - 2) / width, y1)
            renderer.AddActor(actor)
            camera_for(renderer, mesh)
            window.AddRenderer(renderer)
    for c, name in enumerate(columns):
        add_label(background, name, HEADER + c * CELL + CELL // 2, height - HEADER + 7, 0.0)
    for r, name in enumerate(rows):
        add_label(background, name, HEADER - 8, height - HEADER - r * CELL - CELL // 2, 90.0)
    window.Render()
    image = vtkWindowToImageFilter()
    image.SetInput(window)
    image.ReadFrontBufferOff()
    writer = vtkPNGWriter()
    writer.SetFileName(path)
    writer.SetInputConnection(image.GetOutputPort())
    writer.Write()
    window.Finalize()


def gallery(data, methods, path, models=None, parameters=None, report=print):
    """Runs `methods` on one model per category (or on `models`) and draws the gallery into
    `path`. Returns {model: {method: (segments, 1 - Rand index)}}."""
    import kerf
    from vtkmodules.vtkCommonCore import reference
    parameters = parameters or {}
    known = set(kerf.vtkSegmentationBenchmark.GetMethodNames())
    for method in methods:
        if method not in known or method == "human":
            raise BenchmarkError("unknown method '%s' (see python3 -m kerf.benchmark --help)" % method)
    if not models:
        error = reference("")
        found = list(kerf.vtkSegmentationBenchmark.FindModels(data, error))
        if not found:
            raise BenchmarkError(str(error) or "%s holds no models" % data)
        models = first_model_per_category(found)
    rows, pictures, scores = [], [], {}
    for model in models:
        row_pictures = []
        scores[model] = {}
        for method in methods:
            mesh, row = segment(data, method, parameters, model)
            if not row_pictures:
                rows.append("%s (%d)" % (row["Category"], model))
                row_pictures.append((mesh, "Human"))
            row_pictures.append((mesh, "Method"))
            scores[model][method] = (float(row["Segments"]), float(row["RandIndexError"]))
            report("model %d (%s), %s: %g segments, 1 - Rand index %.3f"
                   % (model, row["Category"], method, scores[model][method][0], scores[model][method][1]))
        pictures.append(row_pictures)
    draw(rows, ["human"] + list(methods), pictures, path)
    return scores


def main(argv=None):
    parser = argparse.ArgumentParser(prog="python3 -m kerf.gallery", description=__doc__.split("\n\n")[0])
    parser.add_argument("--data", required=True, help="folder in the benchmark's layout")
    parser.add_argument("--methods", default="ensemble,consensus-cuts,face-clustering,watershed,k-means",
                        help="methods separated by commas (default: %(default)s)")
    parser.add_argument("--models", default="", help="model ids separated by commas (default: one per category)")
    parser.add_argument("-o", "--output", default="gallery.png", help="the picture (default: %(default)s)")
    args = parser.parse_args(argv)
    try:
        models = [int(m) for m in args.models.split(",") if m.strip()] if args.models else None
    except ValueError:
        print("kerf.gallery: error: --models expects ids separated by commas", file=sys.stderr)
        return 1
    try:
        gallery(args.data, [m.strip() for m in args.methods.split(",") if m.strip()], args.output, models)
    except BenchmarkError as error:
        print("kerf.gallery: error: %s" % error, file=sys.stderr)
        return 1
    print("wrote", args.output)
    return 0


if __name__ == "__main__":
    sys.exit(main())
