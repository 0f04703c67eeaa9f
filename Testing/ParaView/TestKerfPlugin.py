# The Kerf ParaView plugin end to end in pvbatch or pvpython: load it, run its proxies, check menus.
import os
import re
import sys
import unittest

from paraview import servermanager
from paraview import simple
from vtkmodules.util.numpy_support import vtk_to_numpy

RADIUS = 2.0
CAMEL = os.path.join(os.environ["KERF_SOURCE_DIR"], "Data", "camel.off")

simple.LoadPlugin(os.environ["KERF_PLUGIN"])


def proxy_definitions(group):
    """Yields (name, XML definition) of every proxy in `group`."""
    definitions = servermanager.ProxyManager().SMProxyManager.GetProxyDefinitionManager()
    iterator = definitions.NewSingleGroupIterator(group)
    iterator.GoToFirstItem()
    while not iterator.IsDoneWithTraversal():
        name = iterator.GetProxyName()
        yield name, definitions.GetProxyDefinition(group, name)
        iterator.GoToNextItem()


class KerfPluginTest(unittest.TestCase):
    def test_surface_descriptors_on_a_sphere(self):
        sphere = simple.Sphere(Radius=RADIUS, ThetaResolution=64, PhiResolution=64)
        descriptors = simple.SurfaceDescriptors(Input=sphere)
        descriptors.UpdatePipeline()
        low, high = descriptors.PointData["MeanCurvature"].GetRange()
        self.assertAlmostEqual(low * RADIUS, 1.0, delta=0.01)
        self.assertAlmostEqual(high * RADIUS, 1.0, delta=0.01)

        output = servermanager.Fetch(descriptors)
        self.assertEqual(output.GetNumberOfPoints(), 64 * 62 + 2)
        mean = vtk_to_numpy(output.GetPointData().GetArray("MeanCurvature"))
        self.assertEqual(len(mean), output.GetNumberOfPoints())
        self.assertLess(abs(mean * RADIUS - 1).mean(), 0.01)

    def test_off_files_open_with_the_kerf_reader(self):
        for reader in (simple.OpenDataFile(CAMEL), simple.OFFReader(FileName=CAMEL)):
            self.assertEqual(reader.SMProxy.GetXMLName(), "KerfOFFReader")
            reader.UpdatePipeline()
            information = reader.GetDataInformation()
            self.assertEqual(information.GetNumberOfPoints(), 9770)
            self.assertEqual(information.GetNumberOfCells(), 19536)

    def test_stroke_cut_applies_at_once(self):
        """A first-time user adds Stroke Cut to the camel and presses Apply: the stroke
        starts across the middle of the surface, so a cut comes out without any error."""
        camel = simple.OpenDataFile(CAMEL)
        camel.UpdatePipeline()
        cut = simple.StrokeCut(Input=camel)
        points = list(cut.StrokePoints)
        bounds = camel.GetDataInformation().GetBounds()
        self.assertEqual(len(points), 6)
        self.assertEqual(points[0], bounds[0])
        self.assertEqual(points[3], bounds[1])
        cut.UpdatePipeline()  # an error would print "ERROR:", which fails the test
        segments = vtk_to_numpy(servermanager.Fetch(cut).GetCellData().GetArray("Segment"))
        self.assertEqual(len(segments), 19536)
        self.assertGreaterEqual(segments.max(), 1)
        self.assertGreaterEqual(servermanager.Fetch(cut, idx=1).GetNumberOfLines(), 1)

    def test_what_paraview_colours_by_after_apply(self):
        """Shown with their defaults, Stroke Cut's output is coloured by its segments, and Harmonic
        Field's (with Stroke Constraints' default stroke, applied at once) by the field clamped to
        its constraint values, -1..1, not by the field, whose least-squares values overshoot far
        beyond them."""
        camel = simple.OpenDataFile(CAMEL)
        camel.UpdatePipeline()
        view = simple.CreateRenderView()
        cut = simple.StrokeCut(Input=camel)
        self.assertEqual(list(simple.Show(cut, view).ColorArrayName), ["CELLS", "Segment"])
        constraints = simple.StrokeConstraints(Input=camel)
        field = simple.HarmonicField(Input=camel, Constraints=constraints)
        self.assertEqual(list(simple.Show(field, view).ColorArrayName), ["POINTS", "HarmonicFieldClamped"])
        colours = simple.GetColorTransferFunction("HarmonicFieldClamped").RGBPoints
        self.assertEqual((colours[0], colours[-4]), (-1.0, 1.0))
        low, high = field.PointData["HarmonicField"].GetRange()
        self.assertLess(low, -10.0)
        self.assertGreater(high, 10.0)
        simple.Delete(view)

    def test_curve_export_splits_the_camel_open_at_the_neck(self):
        """Stroke Cut's cut exported by scissor into the camel's triangles: two charts; split open,
        the same triangles with each point of the cut copied once more, and no point shared by
        the two charts."""
        camel = simple.OpenDataFile(CAMEL)
        camel.UpdatePipeline()
        cut = simple.StrokeCut(Input=camel)
        export = simple.CurveExport(Input=cut, Curves=simple.OutputPort(cut, 1))
        export.UpdatePipeline()
        closed = servermanager.Fetch(export)
        self.assertEqual(closed.GetFieldData().GetArray("ChartCount").GetValue(0), 2)
        cut_edges = servermanager.Fetch(export, idx=1).GetNumberOfLines()
        self.assertGreater(cut_edges, 10)
        export.SplitOpen = 1
        export.UpdatePipeline()
        opened = servermanager.Fetch(export)
        self.assertEqual(opened.GetNumberOfCells(), closed.GetNumberOfCells())
        self.assertEqual(opened.GetNumberOfPoints(), closed.GetNumberOfPoints() + cut_edges)
        self.assertEqual(servermanager.Fetch(export, idx=1).GetNumberOfLines(), 2 * cut_edges)
        charts = vtk_to_numpy(opened.GetCellData().GetArray("Chart"))
        corners = vtk_to_numpy(opened.GetPolys().GetConnectivityArray()).reshape(-1, 3)
        for chart in (0, 1):
            others = set(corners[charts != chart].ravel().tolist())
            self.assertFalse(others & set(corners[charts == chart].ravel().tolist()))

    def test_unwrapped_camel_saves_with_paraviews_writers(self):
        """Chart Parameterization's texture coordinates saved by ParaView's own PLY and OBJ
        writers (File > Save Data) and read back with the same UVs (to single precision)."""
        import tempfile
        camel = simple.OpenDataFile(CAMEL)
        camel.UpdatePipeline()  # Stroke Cut's default stroke is placed from the input's bounds
        cut = simple.StrokeCut(Input=camel)
        export = simple.CurveExport(Input=camel, Curves=simple.OutputPort(cut, 1))
        atlas = simple.ChartParameterization(Input=export)
        atlas.UpdatePipeline()
        uv = vtk_to_numpy(servermanager.Fetch(atlas).GetPointData().GetTCoords())
        folder = tempfile.mkdtemp(prefix="kerf-save-", dir=os.environ.get("KERF_TEST_OUTPUT"))
        for extension in (".ply", ".obj"):
            with self.subTest(format=extension):
                path = os.path.join(folder, "camel-uv" + extension)
                simple.SaveData(path, proxy=atlas)
                back = servermanager.Fetch(simple.OpenDataFile(path))
                read = vtk_to_numpy(back.GetPointData().GetTCoords())
                self.assertEqual(read.shape, uv.shape)
                self.assertLess(abs(read - uv).max(), 1e-6)

    def test_chart_parameterization_flattens_with_either_method(self):
        """Method: LSCM by default, LinABF on request, both giving the camel cut at the neck a
        packed atlas without overlapping charts."""
        camel = simple.OpenDataFile(CAMEL)
        camel.UpdatePipeline()
        cut = simple.StrokeCut(Input=camel)
        export = simple.CurveExport(Input=camel, Curves=simple.OutputPort(cut, 1))
        atlas = simple.ChartParameterization(Input=export)
        self.assertEqual(atlas.Method, "LSCM")
        fields = {}
        for method in ("LSCM", "LinABF"):
            atlas.Method = method
            atlas.UpdatePipeline()
            fields[method] = servermanager.Fetch(atlas).GetFieldData()
            self.assertEqual(fields[method].GetArray("ChartCount").GetValue(0), 2)
            self.assertEqual(fields[method].GetArray("OverlappingChartPairs").GetValue(0), 0)
        self.assertNotEqual(fields["LSCM"].GetArray("MeanShear").GetValue(0),
                            fields["LinABF"].GetArray("MeanShear").GetValue(0))

    def test_point_filters_apply_at_once(self):
        """A first-time user adds Geodesic Distance, Geodesic Seam (on Stroke Cut's cut), ROI
        Scissor, Geodesic Polyline or Geodesic Disc to the camel and presses Apply: their points start at the input's
        bounds, off the surface, and are moved onto it, so each applies without an error."""
        camel = simple.OpenDataFile(CAMEL)
        camel.UpdatePipeline()
        bounds = camel.GetDataInformation().GetBounds()
        low = [bounds[0], 0.5 * (bounds[2] + bounds[3]), 0.5 * (bounds[4] + bounds[5])]
        high = [bounds[1]] + low[1:]
        cut = simple.StrokeCut(Input=camel)
        cases = (
            (simple.GeodesicDistance(Input=camel), "SourcePoint", low),
            (simple.GeodesicSeam(Input=camel, Cut=simple.OutputPort(cut, 1)), "TargetPoint", high),
            (simple.ROIScissor(Input=camel), "ClickPoint", high),
            (simple.GeodesicPolyline(Input=camel), "PathPoints", low + high),
            (simple.GeodesicDisc(Input=camel), "ClickPoint", high),
        )
        for proxy, name, expected in cases:
            with self.subTest(proxy=proxy.SMProxy.GetXMLLabel()):
                values = list(proxy.GetPropertyValue(name))
                self.assertEqual(len(values), len(expected))
                for value, bound in zip(values, expected):
                    self.assertAlmostEqual(value, bound, delta=1e-12)
                proxy.UpdatePipeline()  # an error would print "ERROR:", which fails the test
        distance = servermanager.Fetch(cases[0][0]).GetPointData().GetArray("GeodesicDistance")
        self.assertEqual(distance.GetNumberOfTuples(), 9770)
        # The source lies inside a triangle, one of whose corners is nearest; the camel is one piece.
        low_distance, high_distance = distance.GetRange()
        self.assertTrue(0.0 <= low_distance < 0.01 and high_distance < float("inf"))
        self.assertEqual(servermanager.Fetch(cases[1][0], idx=1).GetNumberOfLines(), 1)
        region = vtk_to_numpy(servermanager.Fetch(cases[2][0]).GetCellData().GetArray("RoiRegion"))
        self.assertTrue(0 < region.sum() < len(region))
        path = servermanager.Fetch(cases[3][0])
        self.assertEqual(path.GetNumberOfLines(), 1)
        # The path runs over the camel's back from one flank to the other: longer than the
        # straight line between its ends, which lie on the surface.
        first, last = path.GetPoint(0), path.GetPoint(path.GetNumberOfPoints() - 1)
        chord = sum((a - b) ** 2 for a, b in zip(first, last)) ** 0.5
        self.assertGreater(path.GetFieldData().GetArray("TotalLength").GetValue(0), chord)
        self.assertTrue(first[0] > bounds[0] and last[0] < bounds[1])
        # The disc of a quarter of the largest side around the high-x click: part of the camel.
        disc = vtk_to_numpy(servermanager.Fetch(cases[4][0]).GetPointData().GetArray("GeodesicDisc"))
        self.assertTrue(0 < disc.sum() < len(disc))

    def test_geodesic_path_loop(self):
        """Geodesic Polyline by its label: a closed loop through three points given as an input, closed
        and simple, the arc length rising to the total length."""
        from vtkmodules.vtkCommonCore import vtkPoints
        from vtkmodules.vtkCommonDataModel import vtkPolyData
        sphere = simple.Sphere(Radius=RADIUS, ThetaResolution=64, PhiResolution=64)
        corners = vtkPoints()
        for point in ((RADIUS, 0.0, 0.0), (0.0, RADIUS, 0.0), (0.0, 0.0, RADIUS)):
            corners.InsertNextPoint(point)
        points = vtkPolyData()
        points.SetPoints(corners)
        producer = simple.TrivialProducer()
        producer.GetClientSideObject().SetOutput(points)
        loop = simple.GeodesicPolyline(Input=sphere, Points=producer, ClosedLoop=1)
        loop.UpdatePipeline()
        output = servermanager.Fetch(loop)
        self.assertEqual(output.GetNumberOfLines(), 1)
        self.assertEqual(output.GetCellData().GetArray("Closed").GetValue(0), 1)
        self.assertEqual(output.GetFieldData().GetArray("SelfCrossings").GetValue(0), 0)
        # The octant's three quarter great circles: 3 pi R / 2.
        total = output.GetFieldData().GetArray("TotalLength").GetValue(0)
        self.assertAlmostEqual(total, 1.5 * 3.141592653589793 * RADIUS, delta=0.01 * 1.5 * 3.141592653589793 * RADIUS)
        arc = vtk_to_numpy(output.GetPointData().GetArray("ArcLength"))
        self.assertTrue((arc[1:] >= arc[:-1]).all() and arc[-1] < total)
        path_points = vtk_to_numpy(output.GetPointData().GetArray("PathPoint"))
        self.assertEqual(sorted(path_points[path_points >= 0].tolist()), [0, 1, 2])

    def test_easy_mesh_cut_applies_at_once(self):
        """A first-time user adds Easy Mesh Cut to the camel and presses Apply: the foreground and
        background strokes of the panel start at the input's low-x and high-x sides, are moved
        onto the surface, and cut the camel in two parts."""
        camel = simple.OpenDataFile(CAMEL)
        camel.UpdatePipeline()
        cut = simple.EasyMeshCut(Input=camel)
        bounds = camel.GetDataInformation().GetBounds()
        self.assertEqual(list(cut.ForegroundPoints)[0], bounds[0])
        self.assertEqual(list(cut.BackgroundPoints)[0], bounds[1])
        cut.UpdatePipeline()  # an error would print "ERROR:", which fails the test
        segment = vtk_to_numpy(servermanager.Fetch(cut).GetCellData().GetArray("Segment"))
        self.assertEqual(sorted(set(segment.tolist())), [0, 1])

    def test_automatic_segmentation_proxies(self):
        """Each automatic-segmentation proxy, by its label, labels every camel face with the
        segments asked for."""
        camel = simple.OpenDataFile(CAMEL)
        for make in (simple.KMeansSegmentation, simple.HierarchicalFaceClustering,
                     simple.ConvexFlooding, simple.WatershedSegmentation):
            segmentation = make(Input=camel, SegmentCount=5)
            segmentation.UpdatePipeline()
            segments = vtk_to_numpy(servermanager.Fetch(segmentation).GetCellData().GetArray("Segment"))
            self.assertEqual(len(segments), 19536)
            self.assertEqual(sorted(set(segments.tolist())), list(range(5)))
            simple.Delete(segmentation)

    def test_core_extraction_proxy(self):
        """Core Extraction Segmentation, by its label and with its defaults, finds the camel's six
        parts itself (no segment count); its Core array marks the body; a larger Feature Radius
        gives no more parts."""
        camel = simple.OpenDataFile(CAMEL)
        segmentation = simple.CoreExtractionSegmentation(Input=camel)
        self.assertEqual(segmentation.FeatureRadius, 0.2)
        segmentation.UpdatePipeline()
        output = servermanager.Fetch(segmentation)
        segments = vtk_to_numpy(output.GetCellData().GetArray("Segment"))
        self.assertEqual(sorted(set(segments.tolist())), list(range(6)))
        self.assertEqual(output.GetFieldData().GetArray("SegmentCount").GetValue(0), 6)
        core = vtk_to_numpy(output.GetCellData().GetArray("Core"))
        self.assertTrue(0 < int(core.sum()) < len(core))
        segmentation.FeatureRadius = 0.5
        segmentation.UpdatePipeline()
        fewer = vtk_to_numpy(servermanager.Fetch(segmentation).GetCellData().GetArray("Segment"))
        self.assertLessEqual(len(set(fewer.tolist())), 6)
        simple.Delete(segmentation)

    def test_ensemble_segmentation_proxy(self):
        """Ensemble Segmentation with its defaults gives the camel the eight segments asked for,
        from five members' votes; with only the consensus cuts voting and no boundary band it gives
        their labels, and the band moves some of their boundaries."""
        camel = simple.OpenDataFile(CAMEL)
        ensemble = simple.EnsembleSegmentation(Input=camel, SegmentCount=8)
        ensemble.UpdatePipeline()
        output = servermanager.Fetch(ensemble)
        segments = vtk_to_numpy(output.GetCellData().GetArray("Segment"))
        self.assertEqual(len(segments), 19536)
        self.assertEqual(sorted(set(segments.tolist())), list(range(8)))
        self.assertEqual(output.GetFieldData().GetArray("Members").GetValue(0), 5)
        self.assertGreaterEqual(output.GetFieldData().GetArray("Atoms").GetValue(0), 8)
        members = dict(SpectralWeight=0.0, ConvexFloodingWeight=0.0, KMeansWeight=0.0, WatershedWeight=0.0)
        alone = simple.EnsembleSegmentation(Input=camel, SegmentCount=8, BoundaryBand=0.0, **members)
        refined = simple.EnsembleSegmentation(Input=camel, SegmentCount=8, **members)
        cuts = simple.ConsensusCutSegmentation(Input=camel, SegmentCount=8)

        def labels(proxy):
            return vtk_to_numpy(servermanager.Fetch(proxy).GetCellData().GetArray("Segment"))

        self.assertEqual(int((labels(alone) != labels(cuts)).sum()), 0)
        # The band moves faces across boundaries, not whole segments (the numbering by first face
        # may change): each refined segment keeps most of one of the cuts' segments.
        import numpy
        overlap = numpy.zeros((8, 8), dtype=int)
        numpy.add.at(overlap, (labels(refined), labels(cuts)), 1)
        self.assertEqual(sorted(overlap.argmax(axis=1).tolist()), list(range(8)))
        moved = 19536 - int(overlap.max(axis=1).sum())
        self.assertGreater(moved, 0)
        self.assertLess(moved, 19536 // 20)
        # The band is the filter Boundary Band Cut: after the ensemble without its band it gives
        # the ensemble's labels.
        unbanded = simple.EnsembleSegmentation(Input=camel, SegmentCount=8, BoundaryBand=0.0)
        recut = simple.BoundaryBandCut(Input=unbanded)
        self.assertEqual(int((labels(recut) != segments).sum()), 0)
        self.assertGreater(servermanager.Fetch(recut).GetFieldData().GetArray("MovedFaces").GetValue(0), 0)
        # Choose Segment Count, between 8 and 9: the count with the smaller of the two CountScores,
        # and at 8 the labels asked for above.
        chosen = simple.EnsembleSegmentation(Input=camel, ChooseSegmentCount=1, MinimumSegmentCount=8,
                                             MaximumSegmentCount=9)
        chosen.UpdatePipeline()
        chosenOutput = servermanager.Fetch(chosen)
        scores = vtk_to_numpy(chosenOutput.GetFieldData().GetArray("CountScores")).tolist()
        self.assertEqual(len(scores), 2)
        count = int(chosenOutput.GetFieldData().GetArray("SegmentCount").GetValue(0))
        self.assertEqual(count, 8 if scores[0] <= scores[1] else 9)
        if count == 8:
            self.assertEqual(int((labels(chosen) != segments).sum()), 0)
        # A sphere has no parts: with the count chosen it stays one segment, no count scored; with
        # Convex Tolerance 0 it gets a count between the defaults 5 and 11.
        ball = simple.Sphere(Radius=1.0, ThetaResolution=32, PhiResolution=32)
        whole = simple.EnsembleSegmentation(Input=ball, ChooseSegmentCount=1)
        whole.UpdatePipeline()
        wholeOutput = servermanager.Fetch(whole)
        self.assertEqual(int(wholeOutput.GetFieldData().GetArray("SegmentCount").GetValue(0)), 1)
        self.assertEqual(wholeOutput.GetFieldData().GetArray("CountScores").GetNumberOfTuples(), 0)
        self.assertEqual(int(labels(whole).max()), 0)
        whole.ConvexTolerance = 0.0
        whole.UpdatePipeline()
        forced = int(servermanager.Fetch(whole).GetFieldData().GetArray("SegmentCount").GetValue(0))
        self.assertGreaterEqual(forced, 5)
        self.assertLessEqual(forced, 11)
        # Hierarchy over the counts 8 to 9: built once, then the Segment Count slider re-labels
        # (Work), every cut has the count asked for, and the tree is in the field data.
        tree = simple.EnsembleSegmentation(Input=camel, UseHierarchy=1, MinimumSegmentCount=8,
                                           MaximumSegmentCount=9, SegmentCount=8)
        tree.UpdatePipeline()
        treeData = servermanager.Fetch(tree).GetFieldData()
        self.assertEqual(treeData.GetAbstractArray("Work").GetValue(0), "hierarchy")
        atoms = int(treeData.GetArray("Atoms").GetValue(0))
        self.assertEqual(treeData.GetArray("MergeFirst").GetNumberOfTuples(), atoms - 1)
        self.assertEqual(treeData.GetArray("CountScores").GetNumberOfTuples(), 2)
        self.assertEqual(int(labels(tree).max()) + 1, 8)
        for k in (2, 5, 12):
            tree.SegmentCount = k
            tree.UpdatePipeline()
            treeData = servermanager.Fetch(tree).GetFieldData()
            self.assertEqual(treeData.GetAbstractArray("Work").GetValue(0), "relabel")
            self.assertEqual(int(treeData.GetArray("SegmentCount").GetValue(0)), k)
        for proxy in (tree, whole, ball, chosen, recut, unbanded, alone, refined, cuts, ensemble):
            simple.Delete(proxy)

    def test_geodesic_distance_on_a_sphere(self):
        """From the north pole of a sphere of radius 2 the farthest point, the south pole, is
        half a great circle away: 2 pi."""
        sphere = simple.Sphere(Radius=RADIUS, ThetaResolution=64, PhiResolution=64)
        distance = simple.GeodesicDistance(Input=sphere, SourcePoint=[0.0, 0.0, RADIUS])
        distance.UpdatePipeline()
        low, high = distance.PointData["GeodesicDistance"].GetRange()
        self.assertAlmostEqual(low, 0.0, delta=1e-9)
        self.assertAlmostEqual(high, 3.141592653589793 * RADIUS, delta=0.02 * 3.141592653589793 * RADIUS)

    def test_geometry_seam_carving_moves_the_handle(self):
        """A cylinder painted handle (z <= 1) / modeling / fixed (z >= 3): Geometry Seams, then
        Geometry Seam Carving with the Transform widget's proxy moving the handle down by 1; the
        stretch splits ring seams, and moving the handle back gives the input's points back."""
        import numpy
        from vtkmodules.util.numpy_support import numpy_to_vtk, numpy_to_vtkIdTypeArray
        from vtkmodules.vtkCommonCore import vtkPoints
        from vtkmodules.vtkCommonDataModel import vtkCellArray, vtkPolyData

        around, rings = 48, 49
        j, i = numpy.meshgrid(numpy.arange(rings), numpy.arange(around), indexing="ij")
        u = 2 * numpy.pi * i.ravel() / around
        z = 4.0 * j.ravel() / (rings - 1)
        triangles = []
        for row in range(rings - 1):
            for col in range(around):
                a, b = row * around + col, row * around + (col + 1) % around
                triangles += [(a, b, b + around), (a, b + around, a + around)]
        cylinder = vtkPolyData()
        points = vtkPoints()
        points.SetData(numpy_to_vtk(numpy.column_stack([numpy.cos(u), numpy.sin(u), z]), deep=True))
        cylinder.SetPoints(points)
        cells = vtkCellArray()
        cells.SetData(numpy_to_vtkIdTypeArray(numpy.arange(0, 3 * len(triangles) + 1, 3, dtype=numpy.int64), deep=True),
                      numpy_to_vtkIdTypeArray(numpy.array(triangles, dtype=numpy.int64).ravel(), deep=True))
        cylinder.SetPolys(cells)
        region = numpy_to_vtk(numpy.where(z <= 1.0, 2.0, numpy.where(z >= 3.0, 0.0, 1.0)), deep=True)
        region.SetName("Region")
        cylinder.GetPointData().AddArray(region)
        producer = simple.TrivialProducer()
        producer.GetClientSideObject().SetOutput(cylinder)

        seams = simple.GeometrySeams(Input=producer, NumberOfRings=10, NumberOfSectors=4)
        # Created before Geometry Seams has run, as in a script: the arrays keep their defaults.
        carving = simple.GeometrySeamCarving(Input=seams)
        self.assertEqual(list(carving.Region), ["POINTS", "Region"])
        self.assertEqual([list(carving.RingSeam), list(carving.Sector), list(carving.EdgeCost)],
                         [["CELLS", "RingSeam"], ["CELLS", "Sector"], ["CELLS", "EdgeCost"]])
        self.assertEqual(carving.HandleTransform.GetXMLName(), "Transform3")
        self.assertEqual(list(carving.GetProperty("StiffnessScale")), [10.0])
        self.assertEqual(list(carving.GetProperty("SalientThreshold")), [0.5])
        carving.HandleTransform.Translate = [0.0, 0.0, -1.0]
        carving.UpdatePipeline()
        stretched = servermanager.Fetch(carving)
        split = stretched.GetFieldData().GetArray("SplitSegments").GetValue(0)
        self.assertGreater(split, 0)
        # A plain cylinder has no feature (its normal-cone angles span less than 1e-3 rad).
        self.assertEqual(stretched.GetFieldData().GetArray("SalientSegments").GetValue(0), 0)
        self.assertGreater(stretched.GetNumberOfPoints(), around * rings)
        self.assertAlmostEqual(stretched.GetBounds()[4], -1.0, places=9)
        carving.HandleTransform.Translate = [0.0, 0.0, -0.5]
        carving.UpdatePipeline()
        carving.HandleTransform.Translate = [0.0, 0.0, 0.0]
        carving.UpdatePipeline()
        back = servermanager.Fetch(carving)
        self.assertEqual(back.GetFieldData().GetArray("SplitSegments").GetValue(0), 0)
        self.assertEqual(back.GetNumberOfPoints(), around * rings)
        moved = vtk_to_numpy(back.GetPoints().GetData()) - vtk_to_numpy(cylinder.GetPoints().GetData())
        self.assertLess(abs(moved).max(), 1e-9)

        # A knob on the modeling region: with Salient Threshold at 0 every segment with any
        # curvature is salient, at the default 0.5 fewer: the property reaches the filter.
        radius = 1.0 + 0.3 * numpy.exp(-((z - 2.0) ** 2 + numpy.angle(numpy.exp(1j * u)) ** 2) / 0.1)
        points.SetData(numpy_to_vtk(numpy.column_stack([radius * numpy.cos(u), radius * numpy.sin(u), z]), deep=True))
        cylinder.Modified()
        carving.HandleTransform.Translate = [0.0, 0.0, -1.0]
        salient = []
        for threshold in (0.5, 0.0):
            carving.SalientThreshold = threshold
            carving.UpdatePipeline()
            salient.append(servermanager.Fetch(carving).GetFieldData().GetArray("SalientSegments").GetValue(0))
        self.assertGreater(salient[1], salient[0])
        self.assertEqual(list(carving.GetProperty("SalientThreshold")), [0.0])

    def test_roi_scissor_selects_a_hoof(self):
        """One click on the camel's front hoof: the hoof, cut at the fetlock, as in the image test."""
        camel = simple.OpenDataFile(CAMEL)
        camel.UpdatePipeline()
        points = vtk_to_numpy(servermanager.Fetch(camel).GetPoints().GetData())
        hoof = points[points[:, 1].argmin()]
        bounds = camel.GetDataInformation().GetBounds()
        diagonal = sum((bounds[2 * i + 1] - bounds[2 * i]) ** 2 for i in range(3)) ** 0.5
        roi = simple.ROIScissor(Input=camel, ClickPoint=list(map(float, hoof)), DiscRadius=0.2 * diagonal)
        roi.UpdatePipeline()
        region = vtk_to_numpy(servermanager.Fetch(roi).GetCellData().GetArray("RoiRegion"))
        self.assertEqual(len(region), 19536)
        self.assertTrue(0 < region.sum() < 0.1 * len(region))
        boundary = servermanager.Fetch(roi, idx=1)
        self.assertEqual(boundary.GetNumberOfLines(), 1)

    def test_geodesic_disc_is_roi_scissors_candidate_region(self):
        """The disc around the camel's front hoof is the candidate region ROI Scissor solves on
        for the same click and radius, vertex for vertex."""
        camel = simple.OpenDataFile(CAMEL)
        camel.UpdatePipeline()
        points = vtk_to_numpy(servermanager.Fetch(camel).GetPoints().GetData())
        hoof = list(map(float, points[points[:, 1].argmin()]))
        bounds = camel.GetDataInformation().GetBounds()
        diagonal = sum((bounds[2 * i + 1] - bounds[2 * i]) ** 2 for i in range(3)) ** 0.5
        disc = simple.GeodesicDisc(Input=camel, ClickPoint=hoof, DiscRadius=0.2 * diagonal)
        roi = simple.ROIScissor(Input=camel, ClickPoint=hoof, DiscRadius=0.2 * diagonal)
        disc.UpdatePipeline()
        roi.UpdatePipeline()
        output = servermanager.Fetch(disc)
        inside = vtk_to_numpy(output.GetPointData().GetArray("GeodesicDisc"))
        candidate = vtk_to_numpy(servermanager.Fetch(roi).GetPointData().GetArray("RoiCandidate"))
        self.assertEqual(len(inside), 9770)
        self.assertEqual(inside.tolist(), candidate.tolist())
        fraction = output.GetFieldData().GetArray("RegionAreaFraction").GetValue(0)
        self.assertTrue(0.0 < fraction < 0.1)
        faces = vtk_to_numpy(output.GetCellData().GetArray("GeodesicDisc"))
        self.assertEqual(len(faces), 19536)

    def test_easy_mesh_cut_cuts_off_a_hoof(self):
        """A foreground stroke on the camel's front hoof and a background stroke on its top, as in
        the image test: the leg below the crease is the foreground, the rest the background."""
        from vtkmodules.vtkCommonCore import vtkIntArray, vtkPoints
        from vtkmodules.vtkCommonDataModel import vtkCellArray, vtkPolyData
        camel = simple.OpenDataFile(CAMEL)
        camel.UpdatePipeline()
        points = vtk_to_numpy(servermanager.Fetch(camel).GetPoints().GetData())
        stroke_points, lines, labels = vtkPoints(), vtkCellArray(), vtkIntArray()
        labels.SetName("Label")
        for point, label in ((points[points[:, 1].argmin()], 1), (points[points[:, 1].argmax()], 0)):
            lines.InsertNextCell(1)
            lines.InsertCellPoint(stroke_points.InsertNextPoint(*map(float, point)))
            labels.InsertNextValue(label)
        strokes = vtkPolyData()
        strokes.SetPoints(stroke_points)
        strokes.SetLines(lines)
        strokes.GetCellData().AddArray(labels)
        producer = simple.TrivialProducer()
        producer.GetClientSideObject().SetOutput(strokes)
        cut = simple.EasyMeshCut(Input=camel, Strokes=producer)
        self.assertEqual(cut.StrokeLabels, "Label")
        cut.UpdatePipeline()
        segment = vtk_to_numpy(servermanager.Fetch(cut).GetCellData().GetArray("Segment"))
        self.assertEqual(len(segment), 19536)
        self.assertTrue(0 < segment.sum() < 0.1 * len(segment))
        boundary = servermanager.Fetch(cut, idx=1)
        self.assertEqual(boundary.GetNumberOfLines(), 1)
        # The same in two steps: Region Growing, then Snake Refinement on its Segment array.
        growing = simple.RegionGrowing(Input=camel, Strokes=producer)
        grown = servermanager.Fetch(growing)
        self.assertEqual(len(vtk_to_numpy(grown.GetPointData().GetArray("Segment"))), 9770)
        snake = simple.SnakeRefinement(Input=growing)
        self.assertEqual(list(snake.SegmentLabels)[-1], "Segment")
        refined = vtk_to_numpy(servermanager.Fetch(snake).GetCellData().GetArray("Segment"))
        self.assertEqual(refined.tolist(), segment.tolist())
        self.assertEqual(servermanager.Fetch(snake, idx=1).GetNumberOfLines(), 1)

    def test_one_name_everywhere(self):
        """Every Kerf proxy's label, without spaces and punctuation, is its class's name without
        the vtk prefix (vtkKerf for the readers and writers, whose generic names VTK may take),
        and its proxy's name without the Kerf prefix: Isoline Cut is vtkIsolineCut in C++ and in
        the kerf Python package, and IsolineCut() in paraview.simple; OFF Reader is
        vtkKerfOFFReader and OFFReader()."""
        sys.path.insert(0, os.environ["PYTHONPATH"].split(os.pathsep)[0])
        import kerf
        names = []
        for group in ("sources", "filters", "writers"):
            for name, definition in proxy_definitions(group):
                if not name.startswith("Kerf"):
                    continue
                label = definition.GetAttribute("label")
                with self.subTest(proxy=name, label=label):
                    one_name = re.sub(r"[^0-9A-Za-z]", "", label)
                    io = one_name.endswith("Reader") or one_name.endswith("Writer")
                    class_name = ("vtkKerf" if io else "vtk") + one_name
                    self.assertEqual(definition.GetAttribute("class"), class_name)
                    self.assertEqual(name, "Kerf" + one_name)
                    self.assertTrue(hasattr(kerf, class_name))
                    if group != "writers":
                        self.assertTrue(hasattr(simple, one_name))
                    names.append(one_name)
        self.assertLessEqual({"StrokeCut", "IsolineCut", "OFFReader", "OFFWriter", "SurfaceDescriptors"}, set(names))

    def test_chart_labels_keep_their_default_in_scripts(self):
        """A script creates a whole pipeline before any of it runs: Chart Parameterization's
        Chart Labels must stay Chart (what Curve Export writes), which ParaView's array list
        would replace by "0" for a still empty input without the NoDefault hint."""
        camel = simple.OpenDataFile(CAMEL)
        self.assertEqual(list(simple.ChartParameterization(Input=camel).ChartLabels), ["CELLS", "Chart"])

    def test_thread_limit_setting(self):
        """Edit > Settings > Kerf: the Thread Limit property sets the limit every Kerf filter of
        the session uses (the settings object is the process's vtkKerfSettings); 0, the
        default, returns to KERF_NUM_THREADS or every core. ParaView's client creates a plugin's
        settings proxies when the plugin loads; a script asks for them once."""
        import kerf
        from paraview.modules.vtkRemotingServerManager import vtkSMPropertyHelper

        servermanager.vtkSMParaViewPipelineController().UpdateSettingsProxies(servermanager.ActiveConnection.Session)
        settings = servermanager.ProxyManager().SMProxyManager.GetProxy("settings", "KerfSettings")
        self.assertIsNotNone(settings)
        limit = vtkSMPropertyHelper(settings, "ThreadLimit")
        self.assertEqual(limit.GetAsInt(), 0)
        self.assertEqual(settings.GetClientSideObject().GetClassName(), "vtkKerfSettings")
        instance = kerf.vtkKerfSettings.GetInstance()

        def set_limit(threads):
            limit.Set(threads)
            settings.UpdateVTKObjects()

        try:
            set_limit(1)
            self.assertEqual(instance.GetThreadLimit(), 1)
            self.assertEqual(instance.GetEffectiveThreadLimit(), 1)
            camel = simple.OpenDataFile(CAMEL)
            ensemble = simple.EnsembleSegmentation(Input=camel, SegmentCount=4)
            ensemble.UpdatePipeline()
            one = vtk_to_numpy(servermanager.Fetch(ensemble).GetCellData().GetArray("Segment")).tolist()
            set_limit(2)
            self.assertEqual(instance.GetEffectiveThreadLimit(), 2)
            again = simple.EnsembleSegmentation(Input=camel, SegmentCount=4)  # a filter of its own
            again.UpdatePipeline()
            two = vtk_to_numpy(servermanager.Fetch(again).GetCellData().GetArray("Segment")).tolist()
            self.assertEqual(len(set(one)), 4)
            self.assertEqual(one, two)
        finally:
            set_limit(0)
        self.assertEqual(instance.GetThreadLimit(), 0)

    def test_filters_are_in_the_kerf_menu(self):
        categories = {}
        for name, definition in proxy_definitions("filters"):
            if name.startswith("Kerf"):
                hints = definition.FindNestedElementByName("Hints")
                menu = hints.FindNestedElementByName("ShowInMenu") if hints is not None else None
                categories[name] = menu.GetAttribute("category") if menu is not None else None
        self.assertLessEqual({"KerfSurfaceDescriptors", "KerfSegmentationReader"}, set(categories))
        self.assertEqual(set(categories.values()), {"Kerf"})


if __name__ == "__main__":
    unittest.main()
