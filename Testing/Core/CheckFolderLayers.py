#!/usr/bin/python3
"""Fails if the folders of Source/Core include each other in a circle.

Each folder of Core is a layer: a file may include headers of its own folder, of the top level
(Error.h, CacheKey.h) and of folders below its own. The folders and their includes form a graph;
this check fails with the circle's folders and the includes that close it when the graph has a
circle, and otherwise prints the layers from the bottom up.
"""
import os
import re
import sys

INCLUDE = re.compile(r'^\s*#\s*include\s*"([A-Za-z0-9_]+)/[^"]+"')


def folder_includes(core):
    """{folder: {included folder: [(file, line), ...]}} over every source file of each folder."""
    graph = {}
    for folder in sorted(os.listdir(core)):
        path = os.path.join(core, folder)
        if not os.path.isdir(path):
            continue
        edges = graph.setdefault(folder, {})
        for root, _, files in os.walk(path):
            for name in sorted(files):
                if not name.endswith((".h", ".cxx", ".hxx", ".txx")):
                    continue
                with open(os.path.join(root, name), encoding="utf-8", errors="replace") as source:
                    for line in source:
                        match = INCLUDE.match(line)
                        if match and match.group(1) != folder:
                            edges.setdefault(match.group(1), []).append(
                                (os.path.relpath(os.path.join(root, name), core), line.strip()))
    return graph


def find_circle(graph):
    """A list of folders [a, b, ..., a] that include each other in a circle, or None."""
    state = {}  # folder -> 1 on the current path, 2 done
    path = []

    def visit(folder):
        state[folder] = 1
        path.append(folder)
        for other in sorted(graph.get(folder, {})):
            if other not in graph:
                continue  # a folder outside Core (a dependency's own "x/y.h")
            if state.get(other) == 1:
                return path[path.index(other):] + [other]
            if other not in state:
                circle = visit(other)
                if circle:
                    return circle
        path.pop()
        state[folder] = 2
        return None

    for folder in sorted(graph):
        if folder not in state:
            circle = visit(folder)
            if circle:
                return circle
    return None


def layers(graph):
    """The folders by height: those that include no other Core folder first."""
    height = {}

    def measure(folder):
        if folder not in height:
            below = [measure(other) for other in graph[folder] if other in graph]
            height[folder] = 1 + max(below) if below else 0
        return height[folder]

    for folder in graph:
        measure(folder)
    rows = {}
    for folder, h in height.items():
        rows.setdefault(h, []).append(folder)
    return [sorted(rows[h]) for h in sorted(rows)]


def main():
    if len(sys.argv) != 2:
        print("usage: CheckFolderLayers.py SOURCE_CORE_DIR", file=sys.stderr)
        return 2
    graph = folder_includes(sys.argv[1])
    if len(graph) < 2:
        print("no folders found under " + sys.argv[1], file=sys.stderr)
        return 1
    circle = find_circle(graph)
    if circle:
        print("Source/Core's folders include each other in a circle: " + " -> ".join(circle), file=sys.stderr)
        for a, b in zip(circle, circle[1:]):
            for file, line in graph[a][b]:
                print("  " + file + ": " + line, file=sys.stderr)
        return 1
    for h, row in enumerate(layers(graph)):
        print("layer %d: %s" % (h, ", ".join(row)))
    return 0


if __name__ == "__main__":
    sys.exit(main())
