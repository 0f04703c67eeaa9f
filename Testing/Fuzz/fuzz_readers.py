#!/usr/bin/env python3
"""Runs generated malformed mesh files through the kerf program, one process per run, and checks
that every run ends in a clean error (exit 1 with "kerf: error: ...") or a valid result (exit 0,
outputs that parse and hold no NaN): never a signal, a sanitizer report, another exit code or a
hang, and never a valid result from a file with NaN or infinite coordinates ("wrong": the reader
turned them into numbers). Prints a table per class; exits 1 if any run failed those checks. Standard library only.

    fuzz_readers.py --kerf build/bin/kerf --seed 1 --count 288 [--first 0] [--jobs 2]
"""
import argparse
import base64
import concurrent.futures
import math
import os
import re
import shutil
import signal
import struct
import subprocess
import sys
import tempfile
import time
import xml.etree.ElementTree as ElementTree
import zlib

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import malformed_meshes  # noqa: E402

OUTCOMES = ["clean error", "valid result", "crash", "hang", "NaN output", "wrong"]
FAILURES = {"crash", "hang", "NaN output", "wrong"}
# Classes whose every file must be refused: a valid result means the reader invented data.
MUST_FAIL = {"non-finite": "a file with non-finite coordinates gave a valid result"}
SANITIZER_MARKS = ("AddressSanitizer", "LeakSanitizer", "UndefinedBehaviorSanitizer",
                   "runtime error:", "Sanitizer:DEADLYSIGNAL")


def lz4_block(source, size):
    """The `size` bytes an LZ4 block (the format of vtkLZ4DataCompressor) holds."""
    out = bytearray()
    i = 0
    while i < len(source):
        token = source[i]
        i += 1
        length = token >> 4
        if length == 15:
            while True:
                i += 1
                length += source[i - 1]
                if source[i - 1] != 255:
                    break
        out += source[i:i + length]
        i += length
        if i >= len(source):
            break
        offset = source[i] | (source[i + 1] << 8)
        i += 2
        match = (token & 15) + 4
        if match == 19:
            while True:
                i += 1
                match += source[i - 1]
                if source[i - 1] != 255:
                    break
        if offset == 0 or offset > len(out):
            raise ValueError("LZ4 block refers before its start")
        begin = len(out) - offset
        for k in range(match):
            out.append(out[begin + k])
    if len(out) != size:
        raise ValueError("LZ4 block of %d bytes, expected %d" % (len(out), size))
    return bytes(out)


def decompress(compressor, data, size):
    if compressor == "vtkZLibDataCompressor":
        return zlib.decompress(data)
    if compressor == "vtkLZ4DataCompressor":
        return lz4_block(data, size)
    raise ValueError("unexpected compressor %r" % compressor)


def vtp_float_arrays(path):
    """(name, values) of every floating-point DataArray in a VTP file written by VTK in binary,
    appended (raw) or ascii mode, zlib- or LZ4-compressed or not. Raises ValueError if the file
    does not parse."""
    with open(path, "rb") as f:
        content = f.read()
    appended = b""
    marker = content.find(b"<AppendedData")
    if marker >= 0:
        # Raw appended bytes are not XML: parse the header alone, read the blocks by offset.
        underscore = content.index(b"_", marker)
        if b'encoding="raw"' not in content[marker:underscore]:
            raise ValueError("unexpected appended-data encoding")
        appended = content[underscore + 1:]
        content = content[:marker] + b"</VTKFile>"
    root = ElementTree.fromstring(content)
    if root.tag != "VTKFile":
        raise ValueError("not a VTKFile")
    word = "<Q" if root.get("header_type") == "UInt64" else "<I"
    word_size = struct.calcsize(word)
    compressor = root.get("compressor")
    arrays = []
    for array in root.iter("DataArray"):
        type_name = array.get("type")
        if type_name not in ("Float32", "Float64"):
            continue
        code = "<f" if type_name == "Float32" else "<d"
        text = "".join((array.text or "").split())
        if array.get("format") == "ascii":
            values = [float(t) for t in (array.text or "").split()]
        elif array.get("format") == "appended":
            at = int(array.get("offset"))
            if compressor is None:
                size = struct.unpack(word, appended[at:at + word_size])[0]
                data = appended[at + word_size:at + word_size + size]
            else:
                blocks, block_size, last_size = struct.unpack("<3" + word[1], appended[at:at + 3 * word_size])
                sizes = struct.unpack("<%d%s" % (blocks, word[1]),
                                      appended[at + 3 * word_size:at + (3 + blocks) * word_size])
                position = at + (3 + blocks) * word_size
                data = bytearray()
                for b, size in enumerate(sizes):
                    expected = last_size if b == blocks - 1 and last_size else block_size
                    data += decompress(compressor, appended[position:position + size], expected)
                    position += size
            values = [v[0] for v in struct.iter_unpack(code, bytes(data))]
        elif array.get("format") == "binary" and compressor is None:
            raw = base64.b64decode(text)
            size = struct.unpack(word, raw[:word_size])[0]
            data = raw[word_size:word_size + size]
            values = [v[0] for v in struct.iter_unpack(code, data)]
        elif array.get("format") == "binary":
            first = base64.b64decode(text[:4 * ((3 * word_size + 2) // 3 + 1)])
            blocks = struct.unpack(word, first[:word_size])[0]
            header_bytes = (3 + blocks) * word_size
            header_chars = 4 * ((header_bytes + 2) // 3)
            header = struct.unpack("<%d%s" % (3 + blocks, word[1]),
                                   base64.b64decode(text[:header_chars])[:header_bytes])
            data = base64.b64decode(text[header_chars:])
            raw = bytearray()
            position = 0
            for b, size in enumerate(header[3:]):
                expected = header[2] if b == header[0] - 1 and header[2] else header[1]
                raw += decompress(compressor, data[position:position + size], expected)
                position += size
            values = [v[0] for v in struct.iter_unpack(code, bytes(raw))]
        else:
            raise ValueError("unexpected DataArray format %r" % array.get("format"))
        arrays.append((array.get("Name") or "Points", values))
    return arrays


def check_outputs(paths, stdout):
    """'valid result', 'NaN output' or 'wrong' for a run that exited with 0."""
    # A standalone nan ("nan", "-nan", "NaN"), not the letters inside a word or a temporary
    # folder's random name.
    if re.search(r"(?<![A-Za-z0-9_])[-+]?nan(?![A-Za-z0-9_])", stdout, re.IGNORECASE):
        return "NaN output", "stdout mentions nan"
    for path in paths:
        if not os.path.exists(path):
            return "wrong", "exit 0 without " + os.path.basename(path)
        try:
            arrays = vtp_float_arrays(path)
        except (ValueError, IndexError, ElementTree.ParseError, zlib.error, struct.error) as e:
            return "wrong", "%s does not parse: %s" % (os.path.basename(path), e)
        for name, values in arrays:
            if any(math.isnan(v) for v in values):
                return "NaN output", "NaN in %s of %s" % (name, os.path.basename(path))
        if not arrays:
            return "wrong", "%s has no points" % os.path.basename(path)
    return "valid result", ""


def run_once(command, timeout, environment):
    """(return code or None on timeout, stdout, stderr)."""
    process = subprocess.Popen(command, stdout=subprocess.PIPE, stderr=subprocess.PIPE,
                               start_new_session=True, env=environment)
    try:
        stdout, stderr = process.communicate(timeout=timeout)
        return process.returncode, stdout.decode(errors="replace"), stderr.decode(errors="replace")
    except subprocess.TimeoutExpired:
        os.killpg(process.pid, signal.SIGKILL)
        stdout, stderr = process.communicate()
        return None, stdout.decode(errors="replace"), stderr.decode(errors="replace")


def classify(code, stdout, stderr, outputs):
    if code is None:
        return "hang", "no exit within the time limit"
    if any(mark in stderr for mark in SANITIZER_MARKS):
        line = next(l for l in stderr.splitlines() if any(m in l for m in SANITIZER_MARKS))
        return "crash", line.strip()[:200]
    if code < 0:
        return "crash", "signal %d (%s)" % (-code, signal.Signals(-code).name)
    if code == 1:
        message = [l for l in stderr.splitlines() if l.startswith("kerf: error: ")]
        if message and len(message[0]) > len("kerf: error: ") + 5:
            return "clean error", message[0][len("kerf: error: "):]
        return "wrong", "exit 1 without an error message: " + stderr.strip()[-200:]
    if code == 0:
        return check_outputs(outputs, stdout)
    return "crash", "exit code %d: %s" % (code, stderr.strip()[-200:])


def run_case(case, args, stroke, environment):
    index, name, ext, data, note = case
    folder = tempfile.mkdtemp(prefix="case-%05d-" % index, dir=args.work)
    mesh = os.path.join(folder, "%05d-%s%s" % (index, name, ext))
    with open(mesh, "wb") as out:
        out.write(data)
    surface = os.path.join(folder, "surface.vtp")
    cut_surface = os.path.join(folder, "cut.vtp")
    curve = os.path.join(folder, "curve.vtp")
    commands = [
        ("descriptors", [args.kerf, "descriptors", mesh, "-o", surface], [surface]),
        ("cut", [args.kerf, "cut", mesh, "--stroke", stroke, "-o", cut_surface, "--curve", curve],
         [cut_surface, curve]),
    ]
    results = []
    for command_name, command, outputs in commands:
        code, stdout, stderr = run_once(command, args.timeout, environment)
        outcome, detail = classify(code, stdout, stderr, outputs)
        if outcome == "valid result" and name in MUST_FAIL:
            outcome, detail = "wrong", MUST_FAIL[name]
        results.append((command_name, outcome, detail))
    if any(outcome in FAILURES for _, outcome, _ in results) and args.keep_failures:
        os.makedirs(args.keep_failures, exist_ok=True)
        shutil.copy(mesh, args.keep_failures)
    shutil.rmtree(folder, ignore_errors=True)
    return index, name, ext, note, results


def table(rows, classes):
    """Markdown table: per class files, runs and runs per outcome."""
    header = ["class", "files", "runs"] + OUTCOMES
    lines = ["| " + " | ".join(header) + " |", "|" + "---|" * len(header)]
    totals = [0] * (len(header) - 1)
    for name in classes + ["all"]:
        if name == "all":
            counts = totals
        else:
            mine = [r for r in rows if r[1] == name]
            outcome_counts = [sum(1 for r in mine for _, o, _ in r[4] if o == k) for k in OUTCOMES]
            counts = [len(mine), sum(len(r[4]) for r in mine)] + outcome_counts
            totals = [a + b for a, b in zip(totals, counts)]
        lines.append("| " + " | ".join([name if name != "all" else "**all**"] + [str(c) for c in counts]) + " |")
    return "\n".join(lines)


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--kerf", required=True, help="the kerf program")
    parser.add_argument("--seed", type=int, default=1)
    parser.add_argument("--count", type=int, default=len(malformed_meshes.CLASSES) * 12)
    parser.add_argument("--first", type=int, default=0)
    parser.add_argument("--jobs", type=int, default=1)
    parser.add_argument("--timeout", type=float, default=30.0, help="seconds per run")
    parser.add_argument("--work", default=None, help="folder for the generated files and outputs")
    parser.add_argument("--keep-failures", default=None, help="copy failing inputs here")
    parser.add_argument("--list-failures", type=int, default=40, help="failures to print")
    args = parser.parse_args()

    args.work = tempfile.mkdtemp(prefix="kerf-fuzz-", dir=args.work)
    stroke = os.path.join(args.work, "stroke.vtk")
    with open(stroke, "w") as out:
        out.write(malformed_meshes.stroke_file_text())
    environment = dict(os.environ)
    # Sanitized builds: report, then exit with a code the classification treats as a crash.
    environment.setdefault("ASAN_OPTIONS", "exitcode=86:detect_leaks=0")
    environment.setdefault("UBSAN_OPTIONS", "print_stacktrace=1:halt_on_error=1:exitcode=87")

    start = time.monotonic()
    rows = []
    cases = malformed_meshes.generate(args.seed, args.count, args.first)
    with concurrent.futures.ThreadPoolExecutor(max_workers=args.jobs) as pool:
        for row in pool.map(lambda case: run_case(case, args, stroke, environment), cases):
            rows.append(row)
    seconds = time.monotonic() - start
    shutil.rmtree(args.work, ignore_errors=True)

    classes = [name for name, _ in malformed_meshes.CLASSES if any(r[1] == name for r in rows)]
    print("kerf fuzzing: seed %d, cases %d..%d, %d files, %d runs in %.0f s"
          % (args.seed, args.first, args.first + args.count - 1, len(rows),
             sum(len(r[4]) for r in rows), seconds))
    print(table(rows, classes))
    failures = [(r, c, o, d) for r in rows for c, o, d in r[4] if o in FAILURES]
    for row, command, outcome, detail in failures[:args.list_failures]:
        print("FAILED %05d-%s%s (%s) kerf %s: %s: %s"
              % (row[0], row[1], row[2], row[3], command, outcome, detail))
    if len(failures) > args.list_failures:
        print("... and %d more failed runs" % (len(failures) - args.list_failures))
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())
