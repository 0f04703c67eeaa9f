"""Kerf's VTK classes cannot clash with VTK's or ParaView's: a class of the same name in both
libraries breaks whichever loads second (one symbol, two definitions). No vtk*.h under Source/
may share its name with a header of the VTK and ParaView this build uses, and the readers,
writers and widgets (where VTK keeps adding classes with generic names) carry the vtkKerf prefix.

Usage: CheckClassNames.py SOURCE_DIR INCLUDE_DIR..."""
import os
import sys

PREFIXED = ("IO", "Widgets")  # folders of Source/ whose classes start with vtkKerf


def headers(root):
    for folder, _, files in os.walk(root):
        for name in files:
            if name.startswith("vtk") and name.endswith(".h"):
                yield folder, name[:-2]


def main(source, include_dirs):
    ours = list(headers(os.path.join(source, "Source")))
    theirs = set()
    for directory in include_dirs:
        theirs.update(name for _, name in headers(directory))
    if len(theirs) < 1000:
        print("ERROR: found only %d VTK and ParaView headers in %s" % (len(theirs), include_dirs))
        return 1
    failures = []
    for folder, name in ours:
        if name in theirs:
            failures.append("%s (%s) is also a class of VTK or ParaView" % (name, folder))
        top = os.path.relpath(folder, os.path.join(source, "Source")).split(os.sep)[0]
        if top in PREFIXED and not name.startswith("vtkKerf"):
            failures.append("%s (%s) needs the vtkKerf prefix" % (name, folder))
    for failure in failures:
        print("ERROR: " + failure)
    print("%d Kerf classes checked against %d VTK and ParaView headers" % (len(ours), len(theirs)))
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1], sys.argv[2:]))
