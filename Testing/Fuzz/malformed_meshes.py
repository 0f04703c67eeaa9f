#!/usr/bin/env python3
"""Deterministic generator of malformed mesh files in every format Kerf reads (.off .ply .obj .stl
.vtp .vtk): valid files of every flavour, then truncated, byte-flipped, overflowing, out-of-range,
mistyped, reordered and non-finite variants. Standard library only.

Case i of seed s is a pure function of (s, i): its own random.Random("s:i"), so any case can be
regenerated alone. Cases cycle through CLASSES, so every class gets the same share.

    malformed_meshes.py --seed 1 --count 500 --output DIR     writes DIR/NNNNN-class.ext and
                                                               DIR/manifest.tsv (index, class, file, note)
"""
import argparse
import base64
import math
import os
import random
import struct
import zlib

# Counts that break naive arithmetic: int32 and int64 limits, values whose products overflow.
HUGE_COUNTS = [
    "2147483647", "2147483648", "4294967295", "4294967296", "4294967297", "1073741824",
    "715827883", "357913942", "4611686018427387904", "9223372036854775807",
    "9223372036854775808", "18446744073709551615", "18446744073709551616",
    "99999999999999999999999", "-1", "-2147483648", "-9223372036854775808", "1e9", "0x10", "3.5",
]
HUGE_INDICES = [2147483647, 2147483648, 4294967295, 4294967296, 9223372036854775807, 1 << 40]
NONFINITE_TOKENS = ["nan", "NaN", "-nan", "inf", "-inf", "Infinity", "1e400", "-1e400", "nan(0x1)"]
EXTENSIONS = [".off", ".ply", ".obj", ".stl", ".vtp", ".vtk"]


# ---- the valid surface every case starts from -----------------------------------------------

def base_mesh(rng):
    """A closed, outward-oriented ellipsoid (semi-axes 1, 0.45, 0.45) as a UV sphere."""
    segments = rng.randint(6, 14)
    rings = rng.randint(4, 8)
    points = [(1.0, 0.0, 0.0)]
    for r in range(1, rings):
        theta = math.pi * r / rings
        for s in range(segments):
            phi = 2.0 * math.pi * s / segments
            points.append((math.cos(theta), 0.45 * math.sin(theta) * math.cos(phi),
                           0.45 * math.sin(theta) * math.sin(phi)))
    points.append((-1.0, 0.0, 0.0))
    last = len(points) - 1

    def ring(r, s):
        return 1 + (r - 1) * segments + s % segments

    faces = []
    for s in range(segments):
        faces.append((0, ring(1, s), ring(1, s + 1)))
        for r in range(1, rings - 1):
            a, b = ring(r, s), ring(r, s + 1)
            c, d = ring(r + 1, s), ring(r + 1, s + 1)
            faces.append((a, c, d))
            faces.append((a, d, b))
        faces.append((last, ring(rings - 1, s + 1), ring(rings - 1, s)))
    return [list(p) for p in points], [list(f) for f in faces]


def stroke_file_text():
    """A polyline across the ellipsoid at x = 0.25 (legacy VTK, ASCII), for `kerf cut --stroke`."""
    radius = 0.45 * math.sqrt(1.0 - 0.25 ** 2)
    points = []
    for k in range(9):
        angle = math.radians(-100.0 + 25.0 * k)
        points.append((0.25, radius * math.cos(angle), radius * math.sin(angle)))
    body = " ".join("%.6f %.6f %.6f" % p for p in points)
    return ("# vtk DataFile Version 4.2\nA stroke across the fuzzing ellipsoid\nASCII\n"
            "DATASET POLYDATA\nPOINTS 9 float\n%s\nLINES 1 10\n9 %s\n"
            % (body, " ".join(str(i) for i in range(9))))


def token(value):
    """Text of a coordinate: strings are emitted verbatim (to inject 'nan', '1e400', ...)."""
    if isinstance(value, str):
        return value
    return repr(float(value))


def as_float(value):
    if isinstance(value, str):
        try:
            return float(value)
        except ValueError:
            return float("nan")
    return float(value)


INT_FORMATS = {"char": "b", "int8": "b", "uchar": "B", "uint8": "B", "short": "h", "int16": "h",
               "ushort": "H", "uint16": "H", "int": "i", "int32": "i", "uint": "I", "uint32": "I",
               "float": "f", "float32": "f", "double": "d", "float64": "d", "int64": "q"}


def integer(value):
    """An integer from a number or token; non-finite values become 0."""
    if isinstance(value, int):
        return value
    number = as_float(value)
    return int(number) if math.isfinite(number) else 0


def real(value, code, endian):
    """Packs a float ('f' or 'd'); values beyond single precision become infinities, as a C cast does."""
    number = as_float(value)
    if code == "f" and math.isfinite(number) and abs(number) > 3.4028234663852886e38:
        number = math.copysign(math.inf, number)
    return struct.pack(endian + code, number)


def pack(value, type_name, endian):
    """Packs value as PLY type type_name, wrapping integers to the type's width."""
    code = INT_FORMATS.get(type_name, "i")
    if code in "fd":
        return real(value, code, endian)
    size = struct.calcsize(code)
    return (integer(value) & ((1 << (8 * size)) - 1)).to_bytes(size, "little" if endian == "<" else "big")


# ---- writers: each takes the mesh and a dict of overrides that malformations set --------------

def write_off(points, faces, o):
    lines = [o.get("off_header", "OFF")]
    lines.append("%s %s %s" % (o.get("nv", len(points)), o.get("nf", len(faces)), o.get("ne", 0)))
    for p in points:
        lines.append(" ".join(token(c) for c in p) + o.get("vertex_suffix", ""))
    for f in faces:
        lines.append("%s %s" % (o.get("face_size", {}).get(id(f), len(f)), " ".join(str(i) for i in f)))
    return (o.get("newline", "\n").join(lines) + o.get("newline", "\n")).encode()


def ply_elements(points, faces, o):
    vertex_type = o.get("vertex_type", "float")
    vertex = {"name": "vertex", "count": len(points),
              "props": [("scalar", vertex_type, "x"), ("scalar", vertex_type, "y"),
                        ("scalar", vertex_type, "z")],
              "rows": [list(p) for p in points]}
    face = {"name": "face", "count": len(faces),
            "props": [("list", o.get("count_type", "uchar"), o.get("index_type", "int"),
                       o.get("index_name", "vertex_indices"))],
            "rows": [[list(f)] for f in faces]}
    return [vertex, face]


def write_ply(elements, fmt, o):
    """elements: dicts with name, count (declared), props (declared), rows, optional data_props
    (the layout the rows are written in, when it differs from the declaration)."""
    endian = "<" if fmt == "binary_little_endian" else ">"
    header = ["ply", o.get("format_line", "format %s 1.0" % fmt)]
    header += o.get("comments", [])
    for e in elements:
        header.append("element %s %s" % (e["name"], e.get("declared_count", e["count"])))
        for p in e["props"]:
            if p[0] == "list":
                header.append("property list %s %s %s" % (p[1], p[2], p[3]))
            else:
                header.append("property %s %s" % (p[1], p[2]))
    header += o.get("extra_header", [])
    if not o.get("no_end_header"):
        header.append("end_header")
    newline = o.get("newline", "\n")
    out = bytearray((newline.join(header) + newline).encode())
    for e in elements:
        props = e.get("data_props", e["props"])
        for row in e["rows"]:
            if fmt == "ascii":
                words = []
                for p, v in zip(props, row):
                    if p[0] == "list":
                        words.append(str(len(v)) if not isinstance(v, tuple) else str(v[0]))
                        items = v if not isinstance(v, tuple) else v[1]
                        words += [token(i) if isinstance(i, (str, float)) else str(i) for i in items]
                    else:
                        words.append(token(v) if p[1] in ("float", "double", "float32", "float64")
                                     else (v if isinstance(v, str) else str(integer(v))))
                out += (" ".join(words) + newline).encode()
            else:
                for p, v in zip(props, row):
                    if p[0] == "list":
                        count = len(v) if not isinstance(v, tuple) else v[0]
                        items = v if not isinstance(v, tuple) else v[1]
                        out += pack(count, p[1], endian)
                        for i in items:
                            out += pack(i, p[2], endian)
                    else:
                        out += pack(v, p[1], endian)
    return bytes(out)


def write_obj(points, faces, o):
    lines = list(o.get("prefix_lines", []))
    for p in points:
        lines.append("v " + " ".join(token(c) for c in p) + o.get("vertex_suffix", ""))
    lines += o.get("after_vertices", [])
    style = o.get("face_style", "plain")
    for f in faces:
        if style == "plain":
            corners = [str(i + 1) for i in f]
        elif style == "relative":
            corners = [str(i - len(points)) for i in f]
        elif style == "vt":
            corners = ["%d/%d" % (i + 1, i + 1) for i in f]
        elif style == "vtvn":
            corners = ["%d/%d/%d" % (i + 1, i + 1, i + 1) for i in f]
        else:  # "vn"
            corners = ["%d//%d" % (i + 1, i + 1) for i in f]
        lines.append("f " + " ".join(corners))
    lines += o.get("suffix_lines", [])
    newline = o.get("newline", "\n")
    return (newline.join(lines) + newline).encode()


def facet_normal(points, f):
    a, b, c = (points[i] if 0 <= i < len(points) else (0, 0, 0) for i in f[:3])
    a, b, c = ([as_float(x) for x in p] for p in (a, b, c))
    u = [b[k] - a[k] for k in range(3)]
    v = [c[k] - a[k] for k in range(3)]
    n = [u[1] * v[2] - u[2] * v[1], u[2] * v[0] - u[0] * v[2], u[0] * v[1] - u[1] * v[0]]
    length = math.sqrt(sum(x * x for x in n)) if all(math.isfinite(x) for x in n) else 0.0
    return [x / length for x in n] if length > 0 else [0.0, 0.0, 0.0]


def stl_triangles(points, faces):
    return [(facet_normal(points, f), [points[i] for i in f[:3]]) for f in faces]


def write_stl_ascii(triangles, o):
    lines = ["solid " + o.get("solid_name", "kerf")]
    for normal, corners in triangles:
        lines.append("  facet normal " + " ".join(token(c) for c in normal))
        lines.append("    outer loop")
        for corner in corners:
            lines.append("      vertex " + " ".join(token(c) for c in corner))
        lines.append("    endloop")
        lines.append("  endfacet")
    if not o.get("no_endsolid"):
        lines.append("endsolid " + o.get("solid_name", "kerf"))
    newline = o.get("newline", "\n")
    return (newline.join(lines) + newline).encode()


def write_stl_binary(triangles, o):
    header = o.get("header", b"binary STL written by Kerf's fuzzing generator").ljust(80, b" ")[:80]
    count = o.get("count", len(triangles))
    out = bytearray(header + struct.pack("<I", count & 0xFFFFFFFF))
    for normal, corners in triangles:
        for c in list(normal) + [c for corner in corners for c in corner]:
            out += real(c, "f", "<")
        out += struct.pack("<H", 0)
    return bytes(out)


VTP_TYPES = {"Int8": "b", "UInt8": "B", "Int16": "h", "UInt16": "H", "Int32": "i", "UInt32": "I",
             "Int64": "q", "UInt64": "Q", "Float32": "f", "Float64": "d"}


def vtp_array(name, type_name, components, values, o, key):
    """An array description for write_vtp: values are numbers (or raw tokens for ASCII)."""
    return {"name": name, "type": type_name, "components": components, "values": values,
            "o": o.get(key, {})}


def encode_binary(values, type_name, header_type, compressed, a_o):
    code = VTP_TYPES.get(type_name, "f")
    raw = bytearray()
    for v in values:
        if code in "fd":
            raw += real(v, code, "<")
        else:
            number = integer(v)
            size = struct.calcsize(code)
            raw += struct.pack("<" + code.upper(), number & ((1 << (8 * size)) - 1))
    raw = bytes(raw)
    word = "<Q" if header_type == "UInt64" else "<I"
    mask = 0xFFFFFFFFFFFFFFFF if header_type == "UInt64" else 0xFFFFFFFF
    if not compressed:
        size = a_o.get("declared_bytes", len(raw))
        return struct.pack(word, size & mask), raw
    block = a_o.get("block_size", 32768)
    blocks = [raw[i:i + block] for i in range(0, len(raw), block)] or [b""]
    packed = [zlib.compress(b) for b in blocks]
    last = len(blocks[-1]) if len(blocks[-1]) != block else 0
    sizes = a_o.get("declared_compressed", [len(p) for p in packed])
    header = [a_o.get("declared_blocks", len(blocks)), a_o.get("declared_block_size", block),
              a_o.get("declared_last", last)] + list(sizes)
    return b"".join(struct.pack(word, h & mask) for h in header), b"".join(packed)


def write_vtp(points, faces, mode, o):
    """mode: ascii, binary, compressed, appended-raw or appended-base64."""
    header_type = o.get("header_type", "UInt64")
    point_type = o.get("point_type", "Float32")
    offsets, connectivity = [], []
    for f in faces:
        connectivity += f
        offsets.append(len(connectivity))
    arrays = {
        "Points": [vtp_array("Points", point_type, o.get("point_components", 3),
                             [c for p in points for c in p], o, "points_array")],
        "PointData": [vtp_array("Scalars_", "Float32", 1, [float(i) for i in range(len(points))],
                                o, "scalars_array")] if o.get("point_data", True) else [],
        "Polys": [vtp_array("connectivity", o.get("index_type", "Int64"), 1,
                            o.get("connectivity", connectivity), o, "connectivity_array"),
                  vtp_array("offsets", o.get("index_type", "Int64"), 1, o.get("offsets", offsets),
                            o, "offsets_array")],
    }
    compressed = mode == "compressed" or o.get("compressed_appended", False)
    root = ('<VTKFile type="%s" version="%s" byte_order="%s" header_type="%s"%s>'
            % (o.get("file_type", "PolyData"), o.get("version", "1.0"),
               o.get("byte_order", "LittleEndian"), header_type,
               ' compressor="%s"' % o.get("compressor", "vtkZLibDataCompressor")
               if compressed else ""))
    piece = ('<Piece NumberOfPoints="%s" NumberOfVerts="0" NumberOfLines="0" NumberOfStrips="0" '
             'NumberOfPolys="%s">' % (o.get("np", len(points)), o.get("npolys", len(faces))))
    xml = ['<?xml version="1.0"?>', root, "  <PolyData>", "    " + piece]
    appended = bytearray()
    for section in o.get("section_order", ["PointData", "Points", "Polys"]):
        xml.append("      <%s>" % section)
        for a in arrays[section]:
            a_o = a["o"]
            attributes = 'type="%s" Name="%s" NumberOfComponents="%s"' % (
                a_o.get("type", a["type"]), a["name"], a_o.get("components", a["components"]))
            fmt = {"ascii": "ascii", "binary": "binary", "compressed": "binary"}.get(mode, "appended")
            if fmt == "ascii":
                text = " ".join(token(v) if isinstance(v, (str, float)) else str(v)
                                for v in a["values"])
                xml.append('        <DataArray %s format="ascii">%s</DataArray>' % (attributes, text))
            elif fmt == "binary":
                header, data = encode_binary(a["values"], a["type"], header_type, compressed, a_o)
                if compressed:
                    text = base64.b64encode(header).decode() + base64.b64encode(data).decode()
                else:
                    text = base64.b64encode(header + data).decode()
                text = a_o.get("text", text)
                xml.append('        <DataArray %s format="binary">%s</DataArray>' % (attributes, text))
            else:
                header, data = encode_binary(a["values"], a["type"], header_type, compressed, a_o)
                offset = a_o.get("offset", len(appended))
                xml.append('        <DataArray %s format="appended" offset="%s"/>'
                           % (attributes, offset))
                if mode == "appended-base64":
                    if compressed:
                        appended += base64.b64encode(header) + base64.b64encode(data)
                    else:
                        appended += base64.b64encode(header + data)
                else:
                    appended += header + data
        xml.append("      </%s>" % section)
    xml += ["    </Piece>", "  </PolyData>"]
    text = "\n".join(xml) + "\n"
    if mode.startswith("appended"):
        encoding = "base64" if mode == "appended-base64" else "raw"
        out = (text + '  <AppendedData encoding="%s">\n   _' % encoding).encode()
        out += bytes(appended) + b"\n  </AppendedData>\n</VTKFile>\n"
        return out
    return (text + "</VTKFile>\n").encode()


def write_legacy(points, faces, fmt, o):
    """Legacy VTK polydata: version 4.2 (cells as 'n id id id') or 5.1 (offsets, connectivity)."""
    version = o.get("version", "4.2")
    binary = fmt == "binary"
    out = bytearray(("# vtk DataFile Version %s\nfuzzing case\n%s\nDATASET %s\n"
                     % (version, "BINARY" if binary else "ASCII",
                        o.get("dataset", "POLYDATA"))).encode())
    point_type = o.get("point_type", "float")
    code = {"float": ">f", "double": ">d"}.get(point_type, ">f")

    def numbers(values, pack_code):
        if binary:
            data = bytearray()
            for v in values:
                if pack_code in (">f", ">d"):
                    data += real(v, pack_code[1], ">")
                else:
                    size = struct.calcsize(pack_code)
                    data += struct.pack(pack_code.upper(), integer(v) & ((1 << (8 * size)) - 1))
            return bytes(data) + b"\n"
        return (" ".join(token(v) if isinstance(v, (str, float)) else str(v) for v in values)
                + "\n").encode()

    out += ("POINTS %s %s\n" % (o.get("np", len(points)), point_type)).encode()
    out += numbers([c for p in points for c in p], code)
    if version.startswith("5"):
        offsets = [0]
        connectivity = []
        for f in faces:
            connectivity += f
            offsets.append(len(connectivity))
        offsets = o.get("offsets", offsets)
        connectivity = o.get("connectivity", connectivity)
        out += ("POLYGONS %s %s\n" % (o.get("n_offsets", len(offsets)),
                                      o.get("n_connectivity", len(connectivity)))).encode()
        out += b"OFFSETS vtktypeint64\n" + numbers(offsets, ">q")
        out += b"CONNECTIVITY vtktypeint64\n" + numbers(connectivity, ">q")
    else:
        cells = o.get("cells", [[len(f)] + list(f) for f in faces])
        flat = [v for c in cells for v in c]
        out += ("POLYGONS %s %s\n" % (o.get("ncells", len(cells)), o.get("size", len(flat)))).encode()
        out += numbers(flat, ">i")
    if o.get("point_data", True):
        out += ("POINT_DATA %s\n" % o.get("npd", len(points))).encode()
        out += ("SCALARS %s %s %s\nLOOKUP_TABLE default\n"
                % (o.get("scalars_name", "distance"), o.get("scalars_type", "float"),
                   o.get("scalars_components", 1))).encode()
        out += numbers(o.get("scalars", [float(i) for i in range(len(points))]), ">f")
    out += o.get("trailer", b"")
    return bytes(out)


# ---- one valid file of a random flavour -------------------------------------------------------

def valid_file(rng, ext=None, points=None, faces=None, o=None):
    """(extension, bytes, flavour) of a well-formed file."""
    if points is None:
        points, faces = base_mesh(rng)
    o = dict(o or {})
    ext = ext or rng.choice(EXTENSIONS)
    if ext == ".off":
        return ext, write_off(points, faces, o), "OFF"
    if ext == ".ply":
        fmt = rng.choice(["ascii", "binary_little_endian", "binary_big_endian"])
        o.setdefault("vertex_type", rng.choice(["float", "double", "float32"]))
        o.setdefault("index_type", rng.choice(["int", "uint", "int32"]))
        return ext, write_ply(ply_elements(points, faces, o), fmt, o), "PLY " + fmt
    if ext == ".obj":
        o.setdefault("face_style", rng.choice(["plain", "plain", "relative"]))
        return ext, write_obj(points, faces, o), "OBJ " + o["face_style"]
    if ext == ".stl":
        if rng.random() < 0.5:
            return ext, write_stl_ascii(stl_triangles(points, faces), o), "STL ascii"
        return ext, write_stl_binary(stl_triangles(points, faces), o), "STL binary"
    if ext == ".vtp":
        mode = rng.choice(["ascii", "binary", "compressed"])
        o.setdefault("header_type", rng.choice(["UInt32", "UInt64"]))
        return ext, write_vtp(points, faces, mode, o), "VTP " + mode
    fmt = rng.choice(["ascii", "binary"])
    o.setdefault("version", rng.choice(["4.2", "5.1"]))
    return ext, write_legacy(points, faces, fmt, o), "VTK %s %s" % (o["version"], fmt)


# ---- malformation classes: each returns (extension, bytes, note) -----------------------------

def c_valid(rng):
    return valid_file(rng)


def c_truncated(rng):
    ext, data, flavour = valid_file(rng)
    cut = rng.choice([0, 1, rng.randrange(len(data)), rng.randrange(len(data)), len(data) - 1,
                      min(len(data) - 1, rng.randrange(1, 200))])
    return ext, data[:cut], "%s cut at byte %d of %d" % (flavour, cut, len(data))


def c_byte_flip(rng):
    ext, data, flavour = valid_file(rng)
    data = bytearray(data)
    flips = rng.choice([1, 1, 2, 4, 16])
    where = []
    for _ in range(flips):
        i = rng.randrange(len(data))
        data[i] = rng.choice([rng.randrange(256), data[i] ^ (1 << rng.randrange(8)), 0, 0xFF,
                              ord(rng.choice("0123456789-.e \n"))])
        where.append(i)
    return ext, bytes(data), "%s with bytes %s changed" % (flavour, where[:4])


def c_splice(rng):
    ext, data, flavour = valid_file(rng)
    i = rng.randrange(len(data))
    j = min(len(data), i + rng.randrange(1, 64))
    action = rng.choice(["delete", "duplicate", "insert", "swap"])
    if action == "delete":
        data = data[:i] + data[j:]
    elif action == "duplicate":
        data = data[:j] + data[i:j] * rng.randint(1, 50) + data[j:]
    elif action == "insert":
        data = data[:i] + bytes(rng.randrange(256) for _ in range(j - i)) + data[i:]
    else:
        k = rng.randrange(len(data))
        data = data[:min(i, k)] + data[max(i, k):] + data[min(i, k):max(i, k)]
    return ext, data, "%s, %s at byte %d" % (flavour, action, i)


def c_garbage(rng):
    ext = rng.choice(EXTENSIONS)
    kind = rng.choice(["empty", "random", "text", "zeros", "magic"])
    if kind == "empty":
        data = b""
    elif kind == "random":
        data = bytes(rng.randrange(256) for _ in range(rng.choice([1, 10, 84, 100, 1000, 5000])))
    elif kind == "text":
        data = "".join(rng.choice("0123456789 .-+e\nabcfvOFplyx/") for _ in range(rng.randrange(1, 3000))).encode()
    elif kind == "zeros":
        data = b"\0" * rng.choice([1, 80, 84, 134, 4096])
    else:
        magic = {".off": b"OFF\n", ".ply": b"ply\n", ".obj": b"v ", ".stl": b"solid ",
                 ".vtp": b"<VTKFile", ".vtk": b"# vtk DataFile Version 4.2\n"}[ext]
        data = magic + bytes(rng.randrange(256) for _ in range(rng.randrange(0, 2000)))
    return ext, data, "garbage: " + kind


def c_count_overflow(rng):
    """Declared counts that overflow 32- and 64-bit arithmetic or are negative."""
    points, faces = base_mesh(rng)
    count = rng.choice(HUGE_COUNTS)
    ext = rng.choice(EXTENSIONS)
    which = rng.choice(["points", "cells"])
    if ext == ".off":
        o = {"nv": count} if which == "points" else {"nf": count}
        return ext, write_off(points, faces, o), "OFF %s count %s" % (which, count)
    if ext == ".ply":
        fmt = rng.choice(["ascii", "binary_little_endian", "binary_big_endian"])
        elements = ply_elements(points, faces, {})
        elements[0 if which == "points" else 1]["declared_count"] = count
        return ext, write_ply(elements, fmt, {}), "PLY %s %s count %s" % (fmt, which, count)
    if ext == ".stl":
        value = integer(count)
        return ext, write_stl_binary(stl_triangles(points, faces), {"count": value}), \
            "STL binary triangle count %s" % count
    if ext == ".vtp":
        mode = rng.choice(["ascii", "binary", "compressed"])
        o = {"np": count} if which == "points" else {"npolys": count}
        return ext, write_vtp(points, faces, mode, o), "VTP %s %s count %s" % (mode, which, count)
    if ext == ".vtk":
        fmt = rng.choice(["ascii", "binary"])
        version = rng.choice(["4.2", "5.1"])
        key = rng.choice(["np", "npd"] if which == "points" else
                         (["ncells", "size"] if version == "4.2" else ["n_offsets", "n_connectivity"]))
        return ext, write_legacy(points, faces, fmt, {"version": version, key: count}), \
            "VTK %s %s %s = %s" % (version, fmt, key, count)
    # OBJ has no counts: an index as large instead.
    faces[rng.randrange(len(faces))][0] = integer(count) - 1
    return ext, write_obj(points, faces, {}), "OBJ face index %s" % count


def c_count_mismatch(rng):
    """Declared counts a little larger or smaller than the data."""
    points, faces = base_mesh(rng)
    delta = rng.choice([-3, -1, 1, 2, 100, 1000000])
    ext = rng.choice([e for e in EXTENSIONS if e != ".obj"])
    which = rng.choice(["points", "cells"])
    n = (len(points) if which == "points" else len(faces)) + delta
    if ext == ".off":
        o = {"nv": n} if which == "points" else {"nf": n}
        return ext, write_off(points, faces, o), "OFF %s count off by %d" % (which, delta)
    if ext == ".ply":
        fmt = rng.choice(["ascii", "binary_little_endian", "binary_big_endian"])
        elements = ply_elements(points, faces, {})
        elements[0 if which == "points" else 1]["declared_count"] = n
        return ext, write_ply(elements, fmt, {}), "PLY %s %s count off by %d" % (fmt, which, delta)
    if ext == ".stl":
        return ext, write_stl_binary(stl_triangles(points, faces), {"count": len(faces) + delta}), \
            "STL binary count off by %d" % delta
    if ext == ".vtp":
        mode = rng.choice(["ascii", "binary", "compressed"])
        o = {"np": n} if which == "points" else {"npolys": n}
        return ext, write_vtp(points, faces, mode, o), "VTP %s %s count off by %d" % (mode, which, delta)
    fmt = rng.choice(["ascii", "binary"])
    version = rng.choice(["4.2", "5.1"])
    if version == "4.2":
        key = rng.choice(["np", "npd", "ncells", "size"])
        base = {"np": len(points), "npd": len(points), "ncells": len(faces), "size": 4 * len(faces)}
    else:
        key = rng.choice(["np", "npd", "n_offsets", "n_connectivity"])
        base = {"np": len(points), "npd": len(points), "n_offsets": len(faces) + 1,
                "n_connectivity": 3 * len(faces)}
    return ext, write_legacy(points, faces, fmt, {"version": version, key: base[key] + delta}), \
        "VTK %s %s %s off by %d" % (version, fmt, key, delta)


def bad_index(rng, n, negative):
    if negative:
        return rng.choice([-1, -2, -n, -n - 1, -2147483648, -(1 << 40)])
    return rng.choice([n, n + 1, n + 1000] + HUGE_INDICES)


def with_bad_indices(rng, negative):
    points, faces = base_mesh(rng)
    n = len(points)
    faces = [list(f) for f in faces]
    for _ in range(rng.choice([1, 1, 3])):
        faces[rng.randrange(len(faces))][rng.randrange(3)] = bad_index(rng, n, negative)
    ext = rng.choice(EXTENSIONS)
    if ext == ".stl":
        # STL has no indices: a facet with a corner count other than three instead.
        triangles = stl_triangles(points, [f if all(0 <= i < n for i in f) else [0, 1, 2] for f in faces])
        k = rng.randrange(len(triangles))
        normal, corners = triangles[k]
        triangles[k] = (normal, corners[:rng.choice([0, 1, 2])] if negative else corners + corners[:rng.choice([1, 3])])
        return ext, write_stl_ascii(triangles, {}), "STL ascii facet with %d corners" % len(triangles[k][1])
    if ext == ".obj":
        faces = [[(i if i < 0 else i) for i in f] for f in faces]
        data = write_obj(points, [[i for i in f] for f in faces], {"face_style": "plain"})
        return ext, data, "OBJ face index %s" % ("negative" if negative else "past the end")
    e, data, flavour = valid_file(rng, ext, points, faces)
    return e, data, "%s with %s face index" % (flavour, "negative" if negative else "out-of-range")


def c_index_out_of_range(rng):
    return with_bad_indices(rng, False)


def c_index_negative(rng):
    return with_bad_indices(rng, True)


def c_nonfinite(rng):
    points, faces = base_mesh(rng)
    for _ in range(rng.choice([1, 1, 2, len(points)])):
        p = points[rng.randrange(len(points))]
        p[rng.randrange(3)] = rng.choice(NONFINITE_TOKENS)
    ext, data, flavour = valid_file(rng, None, points, faces)
    return ext, data, flavour + " with non-finite coordinates"


def c_extreme_values(rng):
    points, faces = base_mesh(rng)
    kind = rng.choice(["huge", "tiny", "float-overflow", "denormal", "mixed", "long-digits"])
    for p in points:
        for k in range(3):
            if kind == "huge":
                p[k] = p[k] * 1e300
            elif kind == "tiny":
                p[k] = p[k] * 1e-300
            elif kind == "float-overflow":
                p[k] = p[k] * 1e39
            elif kind == "denormal":
                p[k] = p[k] * 1e-310
            elif kind == "mixed" and rng.random() < 0.1:
                p[k] = rng.choice([1e308, -1e308, 5e-324])
            elif kind == "long-digits":
                p[k] = "%.60f" % as_float(p[k])
    ext, data, flavour = valid_file(rng, None, points, faces)
    return ext, data, "%s with %s coordinates" % (flavour, kind)


def c_degenerate(rng):
    points, faces = base_mesh(rng)
    kind = rng.choice(["all-equal", "repeat-corner", "duplicate-faces", "single-triangle",
                       "no-faces", "non-manifold", "unreferenced", "one-point"])
    if kind == "all-equal":
        points = [[0.5, 0.5, 0.5] for _ in points]
    elif kind == "repeat-corner":
        f = faces[rng.randrange(len(faces))]
        f[1] = f[0]
    elif kind == "duplicate-faces":
        faces = faces + faces[:rng.randint(1, len(faces))]
    elif kind == "single-triangle":
        points, faces = [[0, 0, 0], [1, 0, 0], [0, 1, 0]], [[0, 1, 2]]
    elif kind == "no-faces":
        faces = []
    elif kind == "non-manifold":
        faces = faces + [[faces[0][0], faces[0][1], len(points)]]
        points = points + [[0.0, 2.0, 0.0]]
    elif kind == "unreferenced":
        points = points + [[5.0, 5.0, 5.0]] * 10
    else:
        points, faces = [[0, 0, 0]], []
    ext, data, flavour = valid_file(rng, None, points, faces)
    return ext, data, "%s, %s" % (flavour, kind)


def c_polygon_size(rng):
    points, faces = base_mesh(rng)
    kind = rng.choice(["empty-face", "one-corner", "two-corners", "big-polygon", "declared-long"])
    f = faces[rng.randrange(len(faces))]
    if kind == "empty-face":
        del f[:]
    elif kind == "one-corner":
        del f[1:]
    elif kind == "two-corners":
        del f[2:]
    elif kind == "big-polygon":
        f[:] = list(range(len(points))) * rng.choice([1, 3])
    ext = rng.choice([".off", ".ply", ".obj", ".vtp", ".vtk"])
    if kind == "declared-long":
        if ext == ".ply":
            fmt = rng.choice(["ascii", "binary_little_endian", "binary_big_endian"])
            count_type = rng.choice(["uchar", "ushort", "int", "uint"])
            elements = ply_elements(points, faces, {"count_type": count_type})
            elements[1]["rows"][rng.randrange(len(faces))] = [(rng.choice([255, 65535, 2147483647, 4294967295, -1]), f)]
            return ext, write_ply(elements, fmt, {"count_type": count_type}), \
                "PLY %s face declaring a huge %s list" % (fmt, count_type)
        if ext == ".vtk":
            cells = [[len(g)] + list(g) for g in faces]
            cells[rng.randrange(len(cells))][0] = rng.choice([4, 100, 2147483647, -1, -2147483648])
            fmt = rng.choice(["ascii", "binary"])
            return ext, write_legacy(points, faces, fmt, {"version": "4.2", "cells": cells}), \
                "VTK 4.2 %s cell claiming more points than the size" % fmt
        if ext == ".off":
            o = {"face_size": {id(f): rng.choice([4, 1000, 2147483647, -3, 0])}}
            return ext, write_off(points, faces, o), "OFF face claiming more corners than it lists"
        ext = ".vtp"
        offsets = []
        total = 0
        for g in faces:
            total += len(g)
            offsets.append(total)
        offsets[-1] = rng.choice([total + 1, total * 1000, 1 << 31, 1 << 40, 1 << 62])
        mode = rng.choice(["ascii", "binary", "compressed"])
        return ext, write_vtp(points, faces, mode, {"offsets": offsets}), \
            "VTP %s last offset past the connectivity" % mode
    e, data, flavour = valid_file(rng, ext, points, faces)
    return e, data, "%s, %s" % (flavour, kind)


def c_ply_property_types(rng):
    points, faces = base_mesh(rng)
    fmt = rng.choice(["ascii", "binary_little_endian", "binary_big_endian"])
    elements = ply_elements(points, faces, {})
    vertex, face = elements
    kind = rng.choice(["indices-scalar", "x-list", "unknown-type", "float-count", "float-indices",
                       "missing-z", "duplicate-x", "int64-count", "double-indices", "char-count",
                       "extra-properties", "colors-normals"])
    if kind == "indices-scalar":
        face["props"] = [("scalar", "int", "vertex_indices")]
        face["data_props"] = [("list", "uchar", "int", "vertex_indices")]
    elif kind == "x-list":
        vertex["props"] = [("list", "uchar", "float", "x"), vertex["props"][1], vertex["props"][2]]
        vertex["data_props"] = [("scalar", "float", "x"), vertex["props"][1], vertex["props"][2]]
    elif kind == "unknown-type":
        vertex["props"] = [("scalar", rng.choice(["float16", "long", "quad", "int128", ""]), "x")] + vertex["props"][1:]
        vertex["data_props"] = [("scalar", "float", "x")] + vertex["props"][1:]
    elif kind == "float-count":
        face["props"] = [("list", "float", "int", "vertex_indices")]
    elif kind == "float-indices":
        face["props"] = [("list", "uchar", "float", "vertex_indices")]
    elif kind == "double-indices":
        face["props"] = [("list", "uchar", "double", "vertex_indices")]
    elif kind == "missing-z":
        vertex["props"] = vertex["props"][:2]
        vertex["rows"] = [r[:2] for r in vertex["rows"]]
    elif kind == "duplicate-x":
        vertex["props"] = vertex["props"] + [("scalar", "float", "x")]
        vertex["rows"] = [r + [r[0]] for r in vertex["rows"]]
    elif kind == "int64-count":
        face["props"] = [("list", "int64", "int", "vertex_indices")]
        face["data_props"] = [("list", "uchar", "int", "vertex_indices")]
    elif kind == "char-count":
        face["props"] = [("list", "char", "int", "vertex_indices")]
    elif kind == "extra-properties":
        vertex["props"] = vertex["props"] + [("scalar", "uchar", "quality"), ("list", "uchar", "float", "weights")]
        vertex["rows"] = [r + [7, [0.5, 0.25]] for r in vertex["rows"]]
        face["props"] = [("scalar", "int", "label")] + face["props"] + [("list", "int", "double", "texcoord")]
        face["rows"] = [[3] + r + [[0.0] * 6] for r in face["rows"]]
    else:
        vertex["props"] = vertex["props"] + [("scalar", "float", "nx"), ("scalar", "float", "ny"),
                                             ("scalar", "float", "nz"), ("scalar", "uchar", "red"),
                                             ("scalar", "uchar", "green"), ("scalar", "uchar", "blue"),
                                             ("scalar", "float", "u"), ("scalar", "float", "v")]
        vertex["rows"] = [r + [0.0, 0.0, 1.0, 200, 100, rng.choice([0, 255, 300, -5]), 0.5, 0.5]
                          for r in vertex["rows"]]
    return ".ply", write_ply(elements, fmt, {}), "PLY %s, %s" % (fmt, kind)


def c_ply_elements(rng):
    points, faces = base_mesh(rng)
    fmt = rng.choice(["ascii", "binary_little_endian", "binary_big_endian"])
    elements = ply_elements(points, faces, {})
    kind = rng.choice(["face-first", "vertex-twice", "no-face", "no-vertex", "extra-element",
                       "empty-elements", "extra-list-element", "zero-property-element"])
    if kind == "face-first":
        elements.reverse()
    elif kind == "vertex-twice":
        elements.append(dict(elements[0]))
    elif kind == "no-face":
        elements = elements[:1]
    elif kind == "no-vertex":
        elements = elements[1:]
    elif kind == "extra-element":
        elements.insert(rng.randint(0, 2), {"name": "material", "count": 2,
                                            "props": [("scalar", "uchar", "red"), ("scalar", "double", "shine")],
                                            "rows": [[1, 0.5], [2, 0.25]]})
    elif kind == "empty-elements":
        elements[0]["count"] = 0
        elements[0]["rows"] = []
        elements[1]["count"] = 0
        elements[1]["rows"] = []
    elif kind == "extra-list-element":
        elements.append({"name": "edge", "count": 3, "props": [("list", "uchar", "int", "vertex_indices")],
                         "rows": [[[0, 1]], [[1, 2]], [[2, 99999]]]})
    else:
        elements.insert(1, {"name": "nothing", "count": rng.choice([0, 5, 4294967295]), "props": [], "rows": []})
    return ".ply", write_ply(elements, fmt, {}), "PLY %s, %s" % (fmt, kind)


def c_ply_header(rng):
    points, faces = base_mesh(rng)
    fmt = rng.choice(["ascii", "binary_little_endian", "binary_big_endian"])
    elements = ply_elements(points, faces, {})
    o = {}
    kind = rng.choice(["no-end-header", "bad-format", "format-version", "crlf", "long-comment",
                       "many-comments", "missing-count", "property-first", "obj-info", "magic",
                       "nul-in-header", "mismatched-format"])
    if kind == "no-end-header":
        o["no_end_header"] = True
    elif kind == "bad-format":
        o["format_line"] = "format " + rng.choice(["binary", "ascii2", "", "binary_middle_endian"]) + " 1.0"
    elif kind == "format-version":
        o["format_line"] = "format %s %s" % (fmt, rng.choice(["2.0", "x", "", "1.0 extra"]))
    elif kind == "crlf":
        o["newline"] = "\r\n"
    elif kind == "long-comment":
        o["comments"] = ["comment " + "x" * rng.choice([300, 5000, 300000])]
    elif kind == "many-comments":
        o["comments"] = ["comment %d" % i for i in range(rng.choice([100, 20000]))]
    elif kind == "missing-count":
        o["extra_header"] = ["element extra"]
    elif kind == "property-first":
        o["comments"] = ["property float w"]
    elif kind == "obj-info":
        o["comments"] = ["obj_info generated", "comment fine"]
    elif kind == "magic":
        data = write_ply(elements, fmt, o)
        return ".ply", rng.choice([b"PLY", b"ply2", b"pl", b" ply"]) + data[3:], "PLY %s bad magic" % fmt
    elif kind == "nul-in-header":
        data = bytearray(write_ply(elements, fmt, o))
        data[rng.randrange(4, 40)] = 0
        return ".ply", bytes(data), "PLY %s NUL byte in the header" % fmt
    else:
        other = rng.choice([f for f in ["ascii", "binary_little_endian", "binary_big_endian"] if f != fmt])
        o["format_line"] = "format %s 1.0" % other
    return ".ply", write_ply(elements, fmt, o), "PLY %s, %s" % (fmt, kind)


def c_stl_binary(rng):
    points, faces = base_mesh(rng)
    triangles = stl_triangles(points, faces)
    kind = rng.choice(["count-zero", "count-short", "count-huge", "trailing", "short-file",
                       "solid-header", "solid-header-ascii-body", "odd-size"])
    o = {}
    if kind == "count-zero":
        o["count"] = 0
    elif kind == "count-short":
        o["count"] = len(triangles) // 2
    elif kind == "count-huge":
        o["count"] = rng.choice([1 << 31, (1 << 32) - 1, len(triangles) + 1, 85899345])
    elif kind == "solid-header":
        o["header"] = b"solid kerf binary file with a misleading header"
    data = write_stl_binary(triangles, o)
    if kind == "trailing":
        data += bytes(rng.randrange(256) for _ in range(rng.choice([1, 2, 49, 50, 51, 1000])))
    elif kind == "short-file":
        data = data[:rng.choice([0, 10, 80, 83, 84, 90, 133])]
    elif kind == "solid-header-ascii-body":
        data = b"solid x" + data[7:]
    elif kind == "odd-size":
        data = data[:-rng.randint(1, 49)]
    return ".stl", data, "STL binary, %s" % kind


def c_stl_ascii(rng):
    points, faces = base_mesh(rng)
    triangles = stl_triangles(points, faces)
    data = write_stl_ascii(triangles, {}).decode()
    lines = data.split("\n")
    kind = rng.choice(["drop-line", "no-endsolid", "two-solids", "vertex-2-numbers", "vertex-words",
                       "uppercase", "color", "long-line", "missing-solid", "tabs-crlf", "extra-words"])
    if kind == "drop-line":
        del lines[rng.randrange(1, len(lines) - 1)]
    elif kind == "no-endsolid":
        lines = lines[:-2]
    elif kind == "two-solids":
        lines = lines + lines
    elif kind == "vertex-2-numbers":
        i = rng.choice([k for k, l in enumerate(lines) if "vertex" in l])
        lines[i] = " ".join(lines[i].split()[:3])
    elif kind == "vertex-words":
        i = rng.choice([k for k, l in enumerate(lines) if "vertex" in l])
        lines[i] = "vertex one two three"
    elif kind == "uppercase":
        lines = [l.upper() for l in lines]
    elif kind == "color":
        lines.insert(1, "color 0.1 0.2 0.3 0.4")
    elif kind == "long-line":
        i = rng.randrange(len(lines))
        lines[i] = lines[i] + " " + "9" * rng.choice([300, 70000])
    elif kind == "missing-solid":
        lines = lines[1:]
    elif kind == "tabs-crlf":
        lines = [l.replace(" ", "\t") + "\r" for l in lines]
    else:
        i = rng.choice([k for k, l in enumerate(lines) if "vertex" in l])
        lines[i] = lines[i] + " 4.0 extra"
    return ".stl", "\n".join(lines).encode(), "STL ascii, %s" % kind


def c_obj_attributes(rng):
    points, faces = base_mesh(rng)
    kind = rng.choice(["vt-missing", "vtvn-missing", "vn-missing", "vt-out-of-range",
                       "vt-negative", "index-zero", "empty-corner", "consistent-vt-vn",
                       "slash-only", "huge-vt"])
    o = {}
    if kind == "vt-missing":
        o["face_style"] = "vt"
    elif kind == "vtvn-missing":
        o["face_style"] = "vtvn"
    elif kind == "vn-missing":
        o["face_style"] = "vn"
    elif kind == "consistent-vt-vn":
        o["face_style"] = "vtvn"
        o["after_vertices"] = (["vt %f %f" % (p[0], p[1]) for p in points]
                               + ["vn 0 0 1" for _ in points])
    else:
        o["face_style"] = "plain"
        o["after_vertices"] = ["vt 0.5 0.5", "vt 0.25 0.75", "vn 0 0 1"]
        data = write_obj(points, faces, o).decode().split("\n")
        faces_at = [k for k, l in enumerate(data) if l.startswith("f ")]
        k = rng.choice(faces_at)
        words = data[k].split()
        corner = {"vt-out-of-range": lambda v: "%s/%d" % (v, rng.choice([3, 99, 2147483647])),
                  "vt-negative": lambda v: "%s/%d" % (v, rng.choice([-3, -99, -2147483648])),
                  "index-zero": lambda v: rng.choice(["0", "0/1", "%s/0" % v, "%s//0" % v]),
                  "empty-corner": lambda v: rng.choice(["/", "//", "/1", "%s/" % v, "", "-"]),
                  "slash-only": lambda v: "%s//" % v,
                  "huge-vt": lambda v: "%s/%s/%s" % (v, "9" * 30, "1")}[kind]
        words[1] = corner(words[1])
        data[k] = " ".join(words)
        return ".obj", "\n".join(data).encode(), "OBJ %s" % kind
    return ".obj", write_obj(points, faces, o), "OBJ %s" % kind


def c_obj_statements(rng):
    points, faces = base_mesh(rng)
    kind = rng.choice(["long-material", "long-line", "continuation", "unknown", "groups",
                       "lines-points", "bad-lines", "two-coordinates", "vertex-colors",
                       "vertex-words", "crlf", "mtllib"])
    o = {"face_style": "plain"}
    if kind == "long-material":
        o["after_vertices"] = ["usemtl " + "m" * rng.choice([99, 100, 101, 1000, 70000])]
    elif kind == "long-line":
        o["suffix_lines"] = ["f " + " ".join(str(1 + i % len(points)) for i in range(rng.choice([30000, 70000])))]
    elif kind == "continuation":
        o["suffix_lines"] = ["f 1 2 \\", "3", "l 1 2 \\"]
    elif kind == "unknown":
        o["prefix_lines"] = ["# comment", "cstype bspline", "deg 3", "xyz 1 2 3", "o object", "s off"]
    elif kind == "groups":
        o["after_vertices"] = ["g one", "usemtl red", "s 1", "g", "o two"]
    elif kind == "lines-points":
        o["suffix_lines"] = ["l 1 2 3", "p 1 2", "l 1/1 2/2"]
    elif kind == "bad-lines":
        o["suffix_lines"] = [rng.choice(["l 1", "l", "p", "p 0", "l 1 %d" % (len(points) + 5),
                                         "p -%d" % (len(points) + 2), "f", "f 1", "f 1 2"])]
    elif kind == "two-coordinates":
        o["vertex_suffix"] = ""
        points[rng.randrange(len(points))] = points[0][:2]
    elif kind == "vertex-colors":
        o["vertex_suffix"] = " 0.5 0.25 1.0"
    elif kind == "vertex-words":
        points[rng.randrange(len(points))][1] = rng.choice(["x", "1..2", "--1", "0x1p3", "1e", ""])
    elif kind == "crlf":
        o["newline"] = "\r\n"
    else:
        o["prefix_lines"] = ["mtllib " + rng.choice(["missing.mtl", "", "../" * 50 + "x.mtl"])]
    return ".obj", write_obj(points, faces, o), "OBJ %s" % kind


def c_vtp_structure(rng):
    points, faces = base_mesh(rng)
    mode = rng.choice(["ascii", "binary", "compressed", "appended-raw", "appended-base64"])
    kind = rng.choice(["components", "offsets-decreasing", "connectivity-out-of-range",
                       "missing-points", "wrong-type", "header-lies", "bad-base64", "unclosed",
                       "appended-offset", "big-endian", "block-header-lies", "file-type",
                       "missing-offsets", "unknown-compressor", "float-offsets", "valid"])
    o = {}
    if kind == "components":
        o["points_array"] = {"components": rng.choice(["0", "2", "4", "-1", "4294967297", "x"])}
    elif kind == "offsets-decreasing":
        offsets = [3 * (i + 1) for i in range(len(faces))]
        offsets[len(offsets) // 2] = 1
        o["offsets"] = offsets
    elif kind == "connectivity-out-of-range":
        connectivity = [i for f in faces for i in f]
        connectivity[rng.randrange(len(connectivity))] = rng.choice([len(points), -1, 1 << 40])
        o["connectivity"] = connectivity
    elif kind == "missing-points":
        o["section_order"] = ["PointData", "Polys"]
    elif kind == "wrong-type":
        o["points_array"] = {"type": rng.choice(["Float16", "String", "Bit", "Int128", ""])}
    elif kind == "header-lies":
        o[rng.choice(["points_array", "offsets_array", "connectivity_array"])] = {
            "declared_bytes": rng.choice([0, 1, 7, 1 << 31, (1 << 32) - 1, 1 << 62])}
        if mode == "compressed":
            mode = "binary"
    elif kind == "bad-base64":
        o["points_array"] = {"text": rng.choice(["!!!!", "AAAA", "A", "====", "AAAAAAAAAAAAAAAA"])}
        mode = "binary"
    elif kind == "appended-offset":
        o[rng.choice(["points_array", "offsets_array", "connectivity_array"])] = {
            "offset": rng.choice(["-1", "999999999", "18446744073709551615", "x", "7"])}
        mode = rng.choice(["appended-raw", "appended-base64"])
    elif kind == "big-endian":
        o["byte_order"] = "BigEndian"
    elif kind == "block-header-lies":
        o[rng.choice(["points_array", "offsets_array", "connectivity_array"])] = rng.choice([
            {"declared_blocks": rng.choice([0, 2, 1 << 31])},
            {"declared_block_size": rng.choice([0, 1, 1 << 40])},
            {"declared_last": rng.choice([1, 1 << 33])},
            {"declared_compressed": [rng.choice([0, 1, 1 << 31, (1 << 32) - 1])]},
            {"block_size": 7}])
        mode = rng.choice(["compressed", "appended-raw"])
        o["compressed_appended"] = mode == "appended-raw"
    elif kind == "file-type":
        o["file_type"] = rng.choice(["UnstructuredGrid", "ImageData", "", "PolyData\" x=\""])
    elif kind == "missing-offsets":
        o["offsets"] = []
    elif kind == "unknown-compressor":
        o["compressor"] = rng.choice(["vtkLZ4DataCompressor", "vtkLZMADataCompressor", "vtkNoSuch"])
        mode = "compressed"
    elif kind == "float-offsets":
        o["index_type"] = rng.choice(["Float32", "Float64", "Int8", "UInt8"])
    data = write_vtp(points, faces, mode, o)
    if kind == "unclosed":
        data = data.replace(b"</Piece>", b"", 1) if rng.random() < 0.5 else data.replace(b"</DataArray>", b"<", 1)
    return ".vtp", data, "VTP %s, %s" % (mode, kind)


def c_vtk_structure(rng):
    points, faces = base_mesh(rng)
    fmt = rng.choice(["ascii", "binary"])
    version = rng.choice(["4.2", "5.1"])
    kind = rng.choice(["dataset-type", "point-type", "offsets-decreasing", "offsets-past-end",
                       "negative-npts", "scalars-components", "field-data", "lookup-table",
                       "no-header", "version-words", "cell-data", "long-token", "normals",
                       "valid-extras"])
    o = {"version": version}
    if kind == "dataset-type":
        o["dataset"] = rng.choice(["UNSTRUCTURED_GRID", "STRUCTURED_POINTS", "polydata", "POLY"])
    elif kind == "point-type":
        o["point_type"] = rng.choice(["double", "int", "bit", "string", "vtkIdType", "unknown", "char"])
    elif kind == "offsets-decreasing":
        o["version"] = "5.1"
        offsets = [3 * i for i in range(len(faces) + 1)]
        offsets[len(offsets) // 2] = rng.choice([1, -5, 1 << 40])
        o["offsets"] = offsets
    elif kind == "offsets-past-end":
        o["version"] = "5.1"
        offsets = [3 * i for i in range(len(faces) + 1)]
        offsets[-1] = rng.choice([3 * len(faces) + 1, 1 << 31, 1 << 62])
        o["offsets"] = offsets
    elif kind == "negative-npts":
        o["version"] = "4.2"
        cells = [[len(f)] + list(f) for f in faces]
        cells[rng.randrange(len(cells))][0] = rng.choice([-1, 0, -2147483648])
        o["cells"] = cells
    elif kind == "scalars-components":
        o["scalars_components"] = rng.choice(["0", "5", "-1", "2147483647", "x"])
    elif kind == "field-data":
        count = rng.choice(["3", "2147483647", "-1", "4611686018427387904", "0"])
        body = ("FIELD FieldData 1\nweights %s %s float\n" % (rng.choice(["1", "3", count]), count)).encode()
        body += (b"1 2 3\n" if fmt == "ascii" else struct.pack(">3f", 1, 2, 3) + b"\n")
        o["trailer"] = body
    elif kind == "lookup-table":
        o["trailer"] = ("LOOKUP_TABLE lut %s\n" % rng.choice(["2", "2147483647", "-1"])).encode() + \
            (b"0 0 0 1 1 1 1 1\n" if fmt == "ascii" else bytes(8) + b"\n")
    elif kind == "no-header":
        ext, data, _ = valid_file(rng, ".vtk", points, faces, {"version": version})
        return ".vtk", data.split(b"\n", 1)[1], "VTK without its first line"
    elif kind == "version-words":
        ext, data, _ = valid_file(rng, ".vtk", points, faces, {"version": version})
        return ".vtk", data.replace(b"Version " + version.encode(), b"Version " + rng.choice([b"x", b"99.9", b"", b"3.0"]), 1), \
            "VTK with an odd version"
    elif kind == "cell-data":
        o["trailer"] = ("CELL_DATA %s\nSCALARS label int 1\nLOOKUP_TABLE default\n"
                        % rng.choice([str(len(faces)), "2147483648", "-1"])).encode() + \
            ((" ".join("1" for _ in faces) + "\n").encode() if fmt == "ascii" else struct.pack(">%di" % len(faces), *([1] * len(faces))) + b"\n")
    elif kind == "long-token":
        o["scalars_name"] = "s" * rng.choice([255, 256, 1000])
    elif kind == "normals":
        o["trailer"] = ("NORMALS n %s\n" % rng.choice(["float", "double", "bit"])).encode() + \
            ((" ".join("0 0 1" for _ in points) + "\n").encode() if fmt == "ascii"
             else struct.pack(">%df" % (3 * len(points)), *([0.0, 0.0, 1.0] * len(points))) + b"\n")
    else:
        o["trailer"] = ("FIELD FieldData 1\nids 1 %d int\n" % len(points)).encode() + \
            ((" ".join(str(i) for i in range(len(points))) + "\n").encode() if fmt == "ascii"
             else struct.pack(">%di" % len(points), *range(len(points))) + b"\n")
    return ".vtk", write_legacy(points, faces, fmt, o), "VTK %s %s, %s" % (o["version"], fmt, kind)


def c_off_structure(rng):
    points, faces = base_mesh(rng)
    kind = rng.choice(["coff", "noff", "4off", "stoff", "binary", "noheader", "counts-on-header",
                       "comments", "face-colors", "missing-counts", "trailing-junk", "nOFF"])
    text = write_off(points, faces, {}).decode()
    lines = text.split("\n")
    if kind == "coff":
        lines[0] = "COFF"
        lines = lines[:2] + [l + " 255 0 0 255" for l in lines[2:2 + len(points)]] + lines[2 + len(points):]
    elif kind == "noff":
        lines[0] = "NOFF"
        lines = lines[:2] + [l + " 0 0 1" for l in lines[2:2 + len(points)]] + lines[2 + len(points):]
    elif kind == "4off":
        lines[0] = "4OFF"
        lines = lines[:2] + [l + " " + rng.choice(["1", "0", "nan", "2"]) for l in lines[2:2 + len(points)]] + lines[2 + len(points):]
    elif kind == "stoff":
        lines[0] = "STOFF"
    elif kind == "binary":
        lines[0] = "OFF BINARY"
    elif kind == "noheader":
        lines = lines[1:]
    elif kind == "counts-on-header":
        lines = ["OFF " + lines[1]] + lines[2:]
    elif kind == "comments":
        lines = ["# comment"] + [l + "  # trailing" for l in lines]
    elif kind == "face-colors":
        lines = lines[:2 + len(points)] + [l + " 0.5 0.5 0.5" for l in lines[2 + len(points):] if l]
    elif kind == "missing-counts":
        lines[1] = rng.choice(["", "5", "x y z"])
    elif kind == "trailing-junk":
        lines.append(rng.choice(["3 0 1 2", "junk", "\0\0\0"]))
    else:
        lines[0] = "nOFF"
    return ".off", "\n".join(lines).encode(), "OFF, %s" % kind


def c_whitespace(rng):
    """Valid files with unusual but legal layout: CRLF, tabs, no final newline, spaces."""
    points, faces = base_mesh(rng)
    ext = rng.choice([".off", ".ply", ".obj", ".stl", ".vtk"])
    kind = rng.choice(["crlf", "no-final-newline", "tabs", "leading-space"])
    o = {"newline": "\r\n"} if kind == "crlf" else {}
    if ext == ".ply":
        data = write_ply(ply_elements(points, faces, {}), "ascii", o)
    elif ext == ".vtk":
        data = write_legacy(points, faces, "ascii", {"version": rng.choice(["4.2", "5.1"])})
        if kind == "crlf":
            data = data.replace(b"\n", b"\r\n")
    elif ext == ".stl":
        data = write_stl_ascii(stl_triangles(points, faces), o)
    elif ext == ".obj":
        data = write_obj(points, faces, dict(o, face_style="plain"))
    else:
        data = write_off(points, faces, o)
    if kind == "no-final-newline":
        data = data.rstrip(b"\r\n")
    elif kind == "tabs" and ext not in (".ply", ".vtk"):
        data = data.replace(b" ", b"\t")
    elif kind == "tabs":
        # PLY and legacy VTK keep their fixed first lines.
        first, rest = data.split(b"\n", 1)
        data = first + b"\n" + rest.replace(b" ", b"\t")
    elif kind == "leading-space" and ext in (".off", ".obj", ".stl"):
        data = b"\n".join(b"  " + l for l in data.split(b"\n"))
    return ext, data, "%s, %s" % (ext, kind)


CLASSES = [
    ("valid", c_valid),
    ("truncated", c_truncated),
    ("byte-flip", c_byte_flip),
    ("splice", c_splice),
    ("garbage", c_garbage),
    ("count-overflow", c_count_overflow),
    ("count-mismatch", c_count_mismatch),
    ("index-out-of-range", c_index_out_of_range),
    ("index-negative", c_index_negative),
    ("non-finite", c_nonfinite),
    ("extreme-values", c_extreme_values),
    ("degenerate", c_degenerate),
    ("polygon-size", c_polygon_size),
    ("ply-property-types", c_ply_property_types),
    ("ply-elements", c_ply_elements),
    ("ply-header", c_ply_header),
    ("stl-binary", c_stl_binary),
    ("stl-ascii", c_stl_ascii),
    ("obj-attributes", c_obj_attributes),
    ("obj-statements", c_obj_statements),
    ("vtp-structure", c_vtp_structure),
    ("vtk-structure", c_vtk_structure),
    ("off-structure", c_off_structure),
    ("whitespace", c_whitespace),
]


def generate(seed, count, first=0):
    """Yields (index, class name, extension, bytes, note) for cases first .. first + count - 1."""
    for index in range(first, first + count):
        name, make = CLASSES[index % len(CLASSES)]
        rng = random.Random("%d:%d" % (seed, index))
        ext, data, note = make(rng)
        yield index, name, ext, data, note


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--seed", type=int, default=1)
    parser.add_argument("--count", type=int, default=len(CLASSES) * 10)
    parser.add_argument("--first", type=int, default=0)
    parser.add_argument("--output", required=True)
    args = parser.parse_args()
    os.makedirs(args.output, exist_ok=True)
    with open(os.path.join(args.output, "manifest.tsv"), "w") as manifest:
        for index, name, ext, data, note in generate(args.seed, args.count, args.first):
            file_name = "%05d-%s%s" % (index, name, ext)
            with open(os.path.join(args.output, file_name), "wb") as out:
                out.write(data)
            manifest.write("%d\t%s\t%s\t%s\n" % (index, name, file_name, note))
    with open(os.path.join(args.output, "stroke.vtk"), "w") as out:
        out.write(stroke_file_text())


if __name__ == "__main__":
    main()
