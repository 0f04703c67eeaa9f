"""Every setter of every Kerf class survives extreme values (2^31 - 1, -1, NaN, inf, 1e308, ...)
without aborting the interpreter, and an execution afterwards either succeeds or reports a clean
error (never a crash, never an uncaught exception)."""
import inspect
import math
import sys
import unittest

import kerf
from vtkmodules.util.misc import calldata_type
from vtkmodules.util.vtkConstants import VTK_STRING
from vtkmodules.vtkCommonCore import vtkCommand
from vtkmodules.vtkFiltersSources import vtkSphereSource

EXTREMES = [2 ** 31 - 1, -2 ** 31, -1, 0, math.nan, math.inf, -math.inf, 1e308, -1e308, 5e-324]
SKIPPED = {"SetInputConnection", "SetInputData", "SetInputArrayToProcess", "SetExecutive",
           "SetInformation", "SetProgressObserver", "SetReferenceCount", "SetDebug",
           "SetGlobalWarningDisplay", "SetProgressText", "SetProgressShiftScale", "SetContainerAlgorithm",
           "SetAbortExecute", "SetAbortExecuteAndUpdateTime", "SetNoPriority", "SetReleaseDataFlag",
           "SetDefaultExecutivePrototype", "SetObjectName"}
ABSTRACT_BASES = {
    "vtkDiscClickAlgorithm", "vtkDrawnStrokeAlgorithm", "vtkStrokeConstraintAlgorithm", "vtkStrokeGrowingAlgorithm"}


def capture_update(algorithm):
    """Updates `algorithm`, returning its status and errors, so nothing prints "ERROR:"."""
    messages = []

    @calldata_type(VTK_STRING)
    def collect(caller, event, message):
        messages.append(message)
    tags = [(o, o.AddObserver(vtkCommand.ErrorEvent, collect)) for o in (algorithm, algorithm.GetExecutive())]
    status = algorithm.GetExecutive().Update()
    for observed, tag in tags:
        observed.RemoveObserver(tag)
    return status, messages


def kerf_classes():
    for name in sorted(dir(kerf)):
        cls = getattr(kerf, name)
        # Abstract bases cannot be made; their setters are their subclasses'.
        if name.startswith("vtk") and inspect.isclass(cls) and name not in ABSTRACT_BASES:
            yield name, cls


def setters(obj):
    for name in sorted(dir(obj)):
        if name.startswith("Set") and name not in SKIPPED and not name.endswith("Macro"):
            yield name, getattr(obj, name)


class SetterExtremes(unittest.TestCase):
    def test_every_setter(self):
        sphere = vtkSphereSource()
        sphere.Update()
        calls = 0
        for class_name, cls in kerf_classes():
            for setter_name, _ in setters(cls()):
                for value in EXTREMES:
                    for arguments in ((value,), (value, 0.0, 0.0, 0.0), (0, value, value, value), (value, value)):
                        obj = cls()
                        errors = []

                        @calldata_type(VTK_STRING)
                        def collect(caller, event, message, errors=errors):
                            errors.append(message)
                        obj.AddObserver(vtkCommand.ErrorEvent, collect)
                        try:
                            getattr(obj, setter_name)(*arguments)
                        except (TypeError, OverflowError, ValueError):
                            continue  # the wrapper refuses the value before C++ sees it
                        calls += 1
                        if hasattr(obj, "GetExecutive") and obj.GetNumberOfInputPorts() > 0:
                            obj.SetInputConnection(0, sphere.GetOutputPort())
                        if hasattr(obj, "GetExecutive") and not class_name.endswith(("Writer", "Benchmark")):
                            status, messages = capture_update(obj)
                            self.assertIn(status, (0, 1))
                            if status == 0:
                                self.assertTrue(messages, "%s.%s%r failed silently" % (class_name, setter_name, arguments))
        self.assertGreater(calls, 200)


if __name__ == "__main__":
    unittest.main(argv=[sys.argv[0]])
