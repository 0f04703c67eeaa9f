# Writes the ParaView state file of each example (states/<example>.pvsm), in pvpython; with a
# folder, also the picture of each (<folder>/example-<example>.png; needs a display):
#   PV_PLUGIN_PATH=build/lib/paraview-5.11/plugins/Kerf pvpython Documentation/examples/save_states.py [FOLDER]
# Each state holds the example's pipeline shown as in its picture. Data file names are written
# relative to the repository (Data/camel.off), so a state opens as it is from the repository's
# top folder, and from anywhere with the Data folder chosen under "Search files under specified
# directory" (paraview --state=...; simple.LoadState(..., data_directory=...)).
import os
import sys

from paraview import simple

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, HERE)
import best_isoline  # noqa: E402
import cut_from_stroke  # noqa: E402
import descriptors  # noqa: E402
import easy_mesh_cut  # noqa: E402
import segmentation_metrics  # noqa: E402
import unwrap  # noqa: E402


def build_cut_from_stroke(view):
    cut_from_stroke.show(cut_from_stroke.neck_stroke(), view)


def build_best_isoline(view):
    field = cut_from_stroke.neck_stroke()
    isoline = best_isoline.best_isoline_pipeline(field)
    cut_from_stroke.show(field, view)
    simple.Hide(simple.OutputPort(field, 1), view)
    simple.ColorBy(simple.GetDisplayProperties(field, view), ("POINTS", "HarmonicFieldClamped"))
    line = simple.Show(isoline, view)
    line.ColorArrayName = ["POINTS", ""]
    line.AmbientColor = line.DiffuseColor = [0.1, 0.1, 0.1]
    line.LineWidth = 3.0


def build_descriptors(view):
    result = descriptors.camel_descriptors()
    result.UpdatePipeline()
    descriptors.show(result, view, descriptors.descriptors()["mean_curvature_5_95"])


def build_segmentation_metrics(view):
    metrics = segmentation_metrics.metrics_pipeline()
    metrics.UpdatePipeline()
    reference = metrics.Input
    cut = reference.Input
    cut_from_stroke.show(cut, view)
    simple.Hide(cut, view)
    simple.ColorBy(simple.Show(reference, view), ("CELLS", "Reference"))


def build_easy_mesh_cut(view):
    cut = easy_mesh_cut.head_cut()
    cut.UpdatePipeline()
    easy_mesh_cut.show(cut, view)


def build_unwrap(view):
    atlas = unwrap.unwrap_pipeline()
    atlas.UpdatePipeline()
    return unwrap.show(atlas, view)


BUILDERS = {"cut_from_stroke": build_cut_from_stroke, "best_isoline": build_best_isoline,
            "descriptors": build_descriptors, "segmentation_metrics": build_segmentation_metrics,
            "unwrap": build_unwrap, "easy_mesh_cut": build_easy_mesh_cut}


def save_state(name, path, picture=None):
    """Builds example `name` alone in a new session and writes its state to `path` (and its
    picture to `picture`)."""
    simple.ResetSession()
    view = simple.CreateView("RenderView", ViewSize=[600, 600])
    simple.AssignViewToLayout(view)
    # A builder that adds views to the view's layout returns the layout: the picture shows it all.
    shown = BUILDERS[name](view) or view
    simple.SaveState(path)
    if picture:
        simple.SaveScreenshot(picture, shown, ImageResolution=[600, 600] if shown is view else [1200, 600])
    with open(path) as f:
        text = f.read()
    with open(path, "w") as f:
        f.write(text.replace(cut_from_stroke.DATA + os.sep, "Data" + os.sep))


if __name__ == "__main__":
    os.makedirs(os.path.join(HERE, "states"), exist_ok=True)
    pictures = sys.argv[1] if len(sys.argv) > 1 else None
    for example in BUILDERS:
        save_state(example, os.path.join(HERE, "states", example + ".pvsm"),
                   os.path.join(pictures, "example-" + example + ".png") if pictures else None)
        print("wrote", os.path.join("states", example + ".pvsm"))
