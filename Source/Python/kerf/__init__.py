"""Kerf: mesh segmentation filters for VTK and ParaView.

Every Kerf class is available directly from this package, for example::

    import kerf
    descriptors = kerf.vtkSurfaceDescriptors()
"""

# The wrapped classes derive from VTK's; importing these first registers their Python types.
from vtkmodules import vtkCommonCore, vtkCommonDataModel, vtkCommonExecutionModel  # noqa: F401

from .KerfIO import *  # noqa: F401,F403
from .KerfFilters import *  # noqa: F401,F403
from .KerfWidgets import *  # noqa: F401,F403
from .KerfEvaluation import *  # noqa: F401,F403

__version__ = "0.1.0"
