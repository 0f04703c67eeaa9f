"""The lists a new filter touches agree with the one list of filters (Source/Filters/CMakeLists.txt)
and with the files: each filter has its proxy, a row in the README's table, a documentation page
that names it and a test that runs it; the README names no class that does not exist; every
benchmark family is registered; and the lists Utilities/new-filter.sh inserts into are in the
order it keeps (Python's sorted()). The test lists themselves are globbed, so there is none to
keep.

Usage: CheckLists.py SOURCE_DIR"""
import glob
import os
import re
import sys


def read(root, *parts):
    with open(os.path.join(root, *parts), encoding="utf-8") as f:
        return f.read()


def cmake_list(text, opening):
    """The entries of `set(<opening> ...)`, quotes removed."""
    match = re.search(r"set\(" + opening + r"\s(.*?)\)", text, re.S)
    return [e.strip('"') for e in match.group(1).split()]


def main(root):
    failures = []
    filters_cmake = read(root, "Source", "Filters", "CMakeLists.txt")
    entries = cmake_list(filters_cmake, "kerf_filters")
    names = [e.split(":")[0] for e in entries]
    for path, opening in (("Source/Filters/CMakeLists.txt", "kerf_filters"),
                          ("Source/Core/CMakeLists.txt", "core_sources")):
        listed = cmake_list(read(root, path), opening)
        if listed != sorted(listed):
            failures.append("%s: %s is not in sorted() order (Utilities/new-filter.sh inserts there): %s"
                            % (path, opening, " ".join(listed)))

    readme = read(root, "README.md")
    table = "\n".join(line for line in readme.split("\n") if line.startswith("| `vtk"))
    pages = {path: read(root, path) for path in glob.glob(os.path.join(root, "Documentation", "filters", "*.md"))}
    tests = [read(root, path) for pattern in ("Testing/Filters/Test*.cxx", "Testing/Python/Test*.py",
                                              "Testing/ParaView/TestKerf*.py")
             for path in glob.glob(os.path.join(root, pattern))]
    for name in names:
        cls = "vtk" + name
        word = re.compile(r"\b" + cls + r"\b")
        if not os.path.exists(os.path.join(root, "Plugins", "ParaView", name + ".xml")):
            failures.append("%s has no proxy Plugins/ParaView/%s.xml" % (cls, name))
        if not word.search(table):
            failures.append("%s has no row in the README's table of filters" % cls)
        if not any(word.search(text) for text in pages.values()):
            failures.append("%s is named on no page of Documentation/filters" % cls)
        if not any(word.search(text) or re.search(r"\b" + name + r"\(", text) for text in tests):
            failures.append("%s is run by no test in Testing/Filters, Testing/Python or Testing/ParaView" % cls)
    classes = {os.path.basename(p)[:-2] for p in glob.glob(os.path.join(root, "Source", "*", "vtk*.h"))}
    for cls in sorted(set(re.findall(r"`(vtk\w+)`", table))):
        if cls not in classes:
            failures.append("the README's table names %s, which Source/ does not have" % cls)
    proxies = {os.path.basename(p)[:-4] for p in glob.glob(os.path.join(root, "Plugins", "ParaView", "*.xml"))}
    for proxy in sorted(proxies):
        xml = read(root, "Plugins", "ParaView", proxy + ".xml")
        if 'ProxyGroup name="filters"' in xml and 'class="vtk%s"' % proxy in xml and proxy not in names:
            failures.append("Plugins/ParaView/%s.xml is a filter proxy that the list of filters lacks" % proxy)

    main_program = read(root, "Testing", "Benchmarks", "KerfBenchmarks.cxx")
    declarations = read(root, "Testing", "Benchmarks", "KerfBenchmarks.h")
    for path in sorted(glob.glob(os.path.join(root, "Testing", "Benchmarks", "*Benchmark.cxx"))):
        family = os.path.basename(path)[: -len("Benchmark.cxx")]
        call = "Register%sBenchmarks" % family
        if call not in main_program or call not in declarations:
            failures.append("the benchmark family %s is not registered (%s in KerfBenchmarks.h and .cxx)"
                            % (family, call))

    for failure in failures:
        print("ERROR: " + failure)
    print("%d filters, %d documentation pages and %d test files checked" % (len(names), len(pages), len(tests)))
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1]))
