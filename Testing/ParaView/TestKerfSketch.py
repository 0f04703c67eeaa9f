# The input drawn in ParaView's view as proxy properties, from pvbatch or pvpython: set from Python as the typed points are, replacing them where given, kept in state files and replayed by traces.
import os
import tempfile
import unittest

from paraview import servermanager
from paraview import simple
from paraview import smtrace
from vtkmodules.util.numpy_support import vtk_to_numpy

CAMEL = os.path.join(os.environ["KERF_SOURCE_DIR"], "Data", "camel.off")
# Data/camel-neck-stroke.vtk: nine points around the neck, on the plane y = 0.3.
NECK = [(0.04321, 0.3, 0.32389), (0.03699, 0.3, 0.349), (0.01963, 0.3, 0.36604), (0.0054, 0.3, 0.37019),
        (-0.00503, 0.3, 0.37019), (-0.01927, 0.3, 0.36604), (-0.03434, 0.3, 0.35249), (-0.04269, 0.3, 0.3296),
        (-0.04083, 0.3, 0.30501)]

simple.LoadPlugin(os.environ["KERF_PLUGIN"])


def flat(points):
    return [float(c) for point in points for c in point]


def cell_array(proxy, name, port=0):
    return vtk_to_numpy(servermanager.Fetch(proxy, idx=port).GetCellData().GetArray(name)).tolist()


def segment_sizes(proxy):
    return vtk_to_numpy(servermanager.Fetch(proxy).GetFieldData().GetArray("SegmentSizes")).tolist()


def camel_points():
    camel = simple.OpenDataFile(CAMEL)
    camel.UpdatePipeline()
    return camel, vtk_to_numpy(servermanager.Fetch(camel).GetPoints().GetData())


class SketchPropertiesTest(unittest.TestCase):
    def test_drawn_strokes_replace_the_typed_stroke(self):
        """Strokes drawn in the view are the properties DrawnStrokePoints and DrawnStrokeSizes: set
        from Python they cut where the same points typed as StrokePoints do, and the typed stroke
        (at first across the middle of the surface) is ignored while any is drawn."""
        camel, _ = camel_points()
        typed = simple.StrokeCut(Input=camel, StrokePoints=flat(NECK))
        drawn = simple.StrokeCut(Input=camel, DrawnStrokePoints=flat(NECK), DrawnStrokeSizes=[len(NECK)])
        default = simple.StrokeCut(Input=camel)
        self.assertEqual(cell_array(drawn, "Segment"), cell_array(typed, "Segment"))
        self.assertNotEqual(cell_array(default, "Segment"), cell_array(drawn, "Segment"))
        sizes = segment_sizes(drawn)
        self.assertEqual(sum(sizes), 19536)
        self.assertTrue(5000 < min(sizes) < 6500, sizes)  # the head: 5,831 faces above the neck plane
        # Two drawn strokes: the neck's split in halves gives the same cut; clearing them brings the
        # typed stroke back.
        drawn.DrawnStrokeSizes = [4, 5]
        self.assertEqual(segment_sizes(drawn), sizes)
        drawn.DrawnStrokePoints = []
        drawn.DrawnStrokeSizes = []
        self.assertEqual(cell_array(drawn, "Segment"), cell_array(default, "Segment"))

    def test_sizes_that_do_not_add_up_are_refused(self):
        from vtkmodules.util.misc import calldata_type
        from vtkmodules.vtkCommonCore import VTK_STRING, vtkCommand
        camel, _ = camel_points()
        cut = simple.StrokeCut(Input=camel, DrawnStrokePoints=flat(NECK), DrawnStrokeSizes=[4, 4])
        algorithm = cut.GetClientSideObject()
        messages = []

        @calldata_type(VTK_STRING)
        def collect(caller, event, message):
            messages.append(message)
        for observed in (algorithm, algorithm.GetExecutive()):
            observed.AddObserver(vtkCommand.ErrorEvent, collect)
        self.assertEqual(algorithm.GetExecutive().Update(), 0)
        self.assertIn("add up to 8 points, but 9 are drawn", messages[0])

    def test_labelled_strokes_replace_the_typed_points_of_their_label(self):
        """Easy Mesh Cut's drawn strokes carry labels (DrawnStrokeLabels): a drawn foreground
        stroke replaces the typed foreground point while the typed background point stays; with a
        drawn background stroke too the typed points are not used at all."""
        camel, points = camel_points()
        hoof = points[points[:, 1].argmin()]
        top = points[points[:, 1].argmax()]
        typed = simple.EasyMeshCut(Input=camel, ForegroundPoints=flat([hoof]), BackgroundPoints=flat([top]))
        hoof_only = simple.EasyMeshCut(Input=camel, BackgroundPoints=flat([top]), DrawnStrokePoints=flat([hoof]),
                                       DrawnStrokeSizes=[1], DrawnStrokeLabels=[1])
        both = simple.EasyMeshCut(Input=camel, DrawnStrokePoints=flat([hoof, top]), DrawnStrokeSizes=[1, 1],
                                  DrawnStrokeLabels=[1, 0])
        self.assertEqual(cell_array(hoof_only, "Segment"), cell_array(typed, "Segment"))
        self.assertEqual(cell_array(both, "Segment"), cell_array(typed, "Segment"))
        sizes = segment_sizes(both)
        self.assertEqual(sum(sizes), 19536)
        self.assertTrue(0 < sizes[1] < 0.1 * 19536, sizes)
        # Region Growing takes the same drawn strokes without a Strokes input.
        growing = simple.RegionGrowing(Input=camel, DrawnStrokePoints=flat([hoof, top]), DrawnStrokeSizes=[1, 1],
                                       DrawnStrokeLabels=[1, 0])
        self.assertEqual(len(cell_array(growing, "Segment")), 19536)
        self.assertEqual(len(segment_sizes(growing)), 2)

    def test_drawn_discs_replace_the_typed_click(self):
        """A disc drawn in the view (DrawnDiscs: x, y, z, radius, subtract) selects what the typed
        click and radius select; a second, subtracting disc makes the candidate region smaller."""
        camel, points = camel_points()
        hoof = [float(c) for c in points[points[:, 1].argmin()]]
        bounds = camel.GetDataInformation().GetBounds()
        diagonal = sum((bounds[2 * i + 1] - bounds[2 * i]) ** 2 for i in range(3)) ** 0.5
        typed = simple.ROIScissor(Input=camel, ClickPoint=hoof, DiscRadius=0.2 * diagonal)
        drawn = simple.ROIScissor(Input=camel, DrawnDiscs=hoof + [0.2 * diagonal, 0])
        self.assertEqual(cell_array(drawn, "RoiRegion"), cell_array(typed, "RoiRegion"))
        disc = simple.GeodesicDisc(Input=camel, DrawnDiscs=hoof + [0.2 * diagonal, 0])
        inside = segment_sizes(disc)[1]
        disc.DrawnDiscs = hoof + [0.2 * diagonal, 0] + hoof + [0.05 * diagonal, 1]
        self.assertLess(segment_sizes(disc)[1], inside)

    def test_clicked_points_replace_the_typed_ones(self):
        """Geodesic Polyline's clicked points (DrawnPoints) replace its typed path points; Geodesic
        Seam's last clicked point replaces its typed target."""
        camel, points = camel_points()
        hoof = points[points[:, 1].argmin()]
        head = points[points[:, 2].argmax()]
        typed = simple.GeodesicPolyline(Input=camel, PathPoints=flat([hoof, head]))
        clicked = simple.GeodesicPolyline(Input=camel, DrawnPoints=flat([hoof, head]))
        clicked_path, typed_path = servermanager.Fetch(clicked), servermanager.Fetch(typed)
        self.assertEqual(clicked_path.GetNumberOfPoints(), typed_path.GetNumberOfPoints())
        self.assertEqual(vtk_to_numpy(clicked_path.GetPoints().GetData()).tolist(),
                         vtk_to_numpy(typed_path.GetPoints().GetData()).tolist())
        cut = simple.StrokeCut(Input=camel, DrawnStrokePoints=flat(NECK))
        seam_typed = simple.GeodesicSeam(Input=camel, Cut=simple.OutputPort(cut, 1), TargetPoint=flat([hoof]))
        seam_clicked = simple.GeodesicSeam(Input=camel, Cut=simple.OutputPort(cut, 1), DrawnPoints=flat([head, hoof]))
        seams = [vtk_to_numpy(servermanager.Fetch(seam, idx=1).GetPoints().GetData()).tolist()
                 for seam in (seam_clicked, seam_typed)]
        self.assertGreater(len(seams[0]), 2)
        self.assertEqual(seams[0], seams[1])

    def test_state_files_keep_the_drawn_input(self):
        """A state file saved with drawn strokes loads them back, and the cut with them."""
        camel, _ = camel_points()
        cut = simple.StrokeCut(Input=camel, DrawnStrokePoints=flat(NECK), DrawnStrokeSizes=[4, 5])
        simple.RenameSource("DrawnNeck", cut)
        expected = cell_array(cut, "Segment")
        folder = tempfile.mkdtemp(prefix="kerf-sketch-", dir=os.environ.get("KERF_TEST_OUTPUT"))
        state = os.path.join(folder, "drawn.pvsm")
        simple.SaveState(state)
        before = set(simple.GetSources().values())
        simple.LoadState(state)
        loaded = [proxy for (name, _), proxy in simple.GetSources().items() if name == "DrawnNeck" and proxy not in before]
        self.assertEqual(len(loaded), 1)
        loaded = loaded[0]
        self.assertEqual(list(loaded.DrawnStrokeSizes), [4, 5])
        self.assertEqual(len(loaded.DrawnStrokePoints), 3 * len(NECK))
        self.assertEqual(cell_array(loaded, "Segment"), expected)

    def test_traces_replay_the_drawn_input(self):
        """A trace of a drawn stroke, as the GUI's apply traces it (the properties modified on the
        proxy), sets the same properties, so replaying it on another Stroke Cut cuts the same way."""
        camel, _ = camel_points()
        cut = simple.StrokeCut(Input=camel)
        smtrace.start_trace()
        modified = smtrace.PropertiesModified(cut)
        cut.DrawnStrokePoints = flat(NECK)
        cut.DrawnStrokeSizes = [len(NECK)]
        modified.finalize()
        trace = smtrace.stop_trace()
        lines = [line.strip() for line in trace.splitlines() if ".DrawnStroke" in line]
        self.assertEqual(len(lines), 2, trace)
        self.assertTrue(lines[1].endswith(".DrawnStrokeSizes = [9]"), lines)
        replay = simple.StrokeCut(Input=camel)
        for line in lines:
            exec("replay" + line[line.index("."):], {"replay": replay})
        self.assertEqual(list(replay.DrawnStrokeSizes), [9])
        self.assertEqual(cell_array(replay, "Segment"), cell_array(cut, "Segment"))


if __name__ == "__main__":
    unittest.main()
