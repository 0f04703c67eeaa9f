"""Every ParaView proxy of the plugin has the defaults of its C++ class: each property's
default_values in Plugins/ParaView/*.xml equals what the freshly made object returns."""
import glob
import math
import os
import sys
import unittest
import xml.etree.ElementTree as ElementTree

import kerf
from vtkmodules.vtkCommonDataModel import vtkDataObject
from vtkmodules.vtkCommonExecutionModel import vtkAlgorithm

SOURCE = os.environ["KERF_SOURCE_DIR"]
PROPERTY_TAGS = ("IntVectorProperty", "DoubleVectorProperty", "StringVectorProperty")


# The sketch widget's proxies (SketchWidget.xml) are not made by users: the panel sets them up,
# and ParaView's vtk3DWidgetRepresentation is not Kerf's.
WIDGET_GROUPS = ("representations", "3d_widgets", "3d_widget_representations")


def proxies():
    """(file, proxy element) for every proxy with a class, the widget's aside."""
    for path in sorted(glob.glob(os.path.join(SOURCE, "Plugins", "ParaView", "*.xml"))):
        for group in ElementTree.parse(path).getroot().iter("ProxyGroup"):
            if group.get("name") in WIDGET_GROUPS:
                continue
            for proxy in group.iter():
                if proxy.get("class"):
                    yield os.path.basename(path), proxy


def defaults(element):
    text = element.get("default_values")
    if text is None:
        return None
    return text.split(element.get("default_values_delimiter", " "))


def exposed_ports(proxy):
    return {int(p.get("port_index", "0")) for p in proxy.iter("InputProperty")}


class ProxyDefaults(unittest.TestCase):
    def check_input_array(self, obj, proxy, element):
        values = defaults(element)
        self.assertIsNotNone(values, "give the array selection its full default (idx;port;conn;assoc;name)")
        self.assertEqual(len(values), 5)
        index, port, connection, association, name = values
        info = obj.GetInputArrayInformation(int(index))
        self.assertEqual(info.Get(vtkDataObject.FIELD_NAME()) or "", name)
        self.assertEqual(info.Get(vtkDataObject.FIELD_ASSOCIATION()), int(association))
        # A proxy shows only its own inputs: an array of an input it does not expose is picked on
        # the inputs it has.
        if info.Get(vtkAlgorithm.INPUT_PORT()) in exposed_ports(proxy):
            self.assertEqual(info.Get(vtkAlgorithm.INPUT_PORT()), int(port))
        self.assertEqual(info.Get(vtkAlgorithm.INPUT_CONNECTION()), int(connection))

    def check_repeated(self, obj, element):
        # A repeated property (a list of points): the number of values per command times the count.
        # Points whose defaults come from the input's bounds (a BoundsDomain) have none of their own.
        if element.find("BoundsDomain") is not None:
            return
        count = getattr(obj, "Get" + element.get("set_number_command")[3:])()
        expected = defaults(element) or []
        self.assertEqual(count * int(element.get("number_of_elements_per_command")), len(expected))

    def check_value(self, obj, element):
        getter = getattr(obj, "Get" + element.get("command")[3:])
        actual = getter()
        expected = defaults(element)
        if element.tag == "StringVectorProperty":
            self.assertEqual(actual or "", (expected or [""])[0])
            return
        self.assertIsNotNone(expected, "numbers need a default in the XML")
        actual = list(actual) if isinstance(actual, (tuple, list)) else [actual]
        self.assertEqual(len(actual), len(expected))
        for a, e in zip(actual, expected):
            self.assertTrue(math.isclose(float(a), float(e), rel_tol=1e-12), "%r != %r" % (a, e))

    def test_every_property_default(self):
        checked = 0
        for file, proxy in proxies():
            obj = getattr(kerf, proxy.get("class"))()
            for element in proxy:
                if element.tag not in PROPERTY_TAGS or not element.get("command"):
                    continue
                with self.subTest(proxy=proxy.get("name"), property=element.get("name"), file=file):
                    if element.get("command") == "SetInputArrayToProcess":
                        self.check_input_array(obj, proxy, element)
                    elif element.get("repeat_command") == "1":
                        self.check_repeated(obj, element)
                    else:
                        self.check_value(obj, element)
                    checked += 1
        self.assertGreater(checked, 30)


if __name__ == "__main__":
    unittest.main(argv=[sys.argv[0]])
