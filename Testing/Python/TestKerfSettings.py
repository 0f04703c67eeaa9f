# kerf.vtkKerfSettings from Python: one instance per process, the thread limit it sets in Kerf's
# Core (0 returns to KERF_NUM_THREADS or every core), a negative limit refused, and the ensemble's
# labels the same on one thread and on two.
import os
import unittest

import kerf
from TestCoreExtraction import camel
from vtkmodules.util.numpy_support import vtk_to_numpy
from vtkmodules.vtkCommonCore import vtkCommand


class KerfSettingsTest(unittest.TestCase):
    def setUp(self):
        self.environment = os.environ.pop("KERF_NUM_THREADS", None)

    def tearDown(self):
        kerf.vtkKerfSettings.GetInstance().SetThreadLimit(0)
        os.environ.pop("KERF_NUM_THREADS", None)
        if self.environment is not None:
            os.environ["KERF_NUM_THREADS"] = self.environment

    def test_one_instance(self):
        settings = kerf.vtkKerfSettings()
        self.assertEqual(settings.GetThreadLimit(), 0)  # the default
        self.assertIs(settings, kerf.vtkKerfSettings.GetInstance())
        settings.SetThreadLimit(3)
        self.assertEqual(kerf.vtkKerfSettings().GetThreadLimit(), 3)

    def test_the_limit_reaches_kerf(self):
        settings = kerf.vtkKerfSettings.GetInstance()
        cores = kerf.vtkKerfSettings.GetNumberOfCores()
        self.assertGreaterEqual(cores, 1)
        self.assertEqual(settings.GetEffectiveThreadLimit(), cores)
        os.environ["KERF_NUM_THREADS"] = "5"  # read at each call
        self.assertEqual(settings.GetEffectiveThreadLimit(), 5)
        settings.SetThreadLimit(1)
        self.assertEqual(settings.GetEffectiveThreadLimit(), 1)  # the setting wins
        settings.SetThreadLimit(0)
        self.assertEqual(settings.GetEffectiveThreadLimit(), 5)
        del os.environ["KERF_NUM_THREADS"]
        self.assertEqual(settings.GetEffectiveThreadLimit(), cores)

    def test_a_negative_limit_is_refused(self):
        settings = kerf.vtkKerfSettings.GetInstance()
        settings.SetThreadLimit(2)
        errors = []
        tag = settings.AddObserver(vtkCommand.ErrorEvent, lambda caller, event: errors.append(event))
        settings.SetThreadLimit(-1)
        settings.RemoveObserver(tag)
        self.assertEqual(len(errors), 1)
        self.assertEqual(settings.GetThreadLimit(), 2)  # unchanged

    def test_the_ensemble_is_the_same_on_one_thread_and_two(self):
        surface = camel()
        labels = []
        for threads in (1, 2):
            kerf.vtkKerfSettings.GetInstance().SetThreadLimit(threads)
            ensemble = kerf.vtkEnsembleSegmentation()
            ensemble.SetInputData(surface)
            ensemble.SetChooseSegmentCount(True)
            self.assertEqual(ensemble.GetExecutive().Update(), 1)
            labels.append(vtk_to_numpy(ensemble.GetOutput().GetCellData().GetArray("Segment")).tolist())
        self.assertEqual(len(labels[0]), surface.GetNumberOfCells())
        self.assertGreater(len(set(labels[0])), 1)
        self.assertEqual(labels[0], labels[1])


if __name__ == "__main__":
    unittest.main()
