#!/usr/bin/env python3
"""Writes the benchmark log (Documentation/benchmark-log.md) from KerfBenchmarks' JSON output.

    build/bin/KerfBenchmarks --benchmark_repetitions=3 --benchmark_filter=... \\
        --benchmark_out=run.json --benchmark_out_format=json
    /usr/bin/python3 Utilities/benchmark-log.py run.json [more.json ...] -o Documentation/benchmark-log.md
    /usr/bin/python3 Utilities/benchmark-log.py --append new.json -o Documentation/benchmark-log.md

One section per run (its date, machine and build from the JSON's context), one table per
benchmark family (the name up to its first '/'), one row per benchmark: the median of its
repetitions (or its one run), the spread (min-max over the repetitions, as a percentage of the
median), the iterations and the counters it reports. The documentation pages cite benchmarks by
name; their figures come from here, so a page states what a method costs, and this log when and
where it was measured. With --append the log keeps its sections and gains one for each run it
does not hold yet (a run is known by its heading: its date and machine), so that the log grows run
by run without the earlier runs' JSON."""
import argparse
import collections
import json
import statistics
import sys

UNIT = {"ns": 1e-6, "us": 1e-3, "ms": 1.0, "s": 1e3}


def milliseconds(value, unit):
    return value * UNIT[unit]


def format_time(ms):
    if ms >= 1000.0:
        return "%.3g s" % (ms / 1000.0)
    if ms >= 1.0:
        return "%.3g ms" % ms
    return "%.3g us" % (ms * 1000.0)


def format_counter(value):
    if float(value).is_integer() and abs(value) < 1e12:
        return "{:,}".format(int(value))
    return "%.4g" % value


STANDARD = {"name", "family_index", "per_family_instance_index", "run_name", "run_type", "repetitions",
            "repetition_index", "threads", "iterations", "real_time", "cpu_time", "time_unit",
            "aggregate_name", "aggregate_unit", "error_occurred", "error_message", "label"}


def section(run):
    context = run["context"]
    runs = collections.OrderedDict()
    for bench in run["benchmarks"]:
        if bench.get("run_type") != "iteration":
            continue  # aggregates are recomputed from the repetitions
        runs.setdefault(bench["run_name"], []).append(bench)
    lines = []
    caches = ", ".join("L%d %s %d KiB" % (c["level"], c["type"].lower(), c["size"] // 1024)
                       for c in context.get("caches", []))
    lines.append("## Run of %s on %s" % (context.get("date", "?"), context.get("host_name", "?")))
    lines.append("")
    lines.append("%s, %s CPUs at %s MHz (%s); load average %s; Kerf's sparse Cholesky %s, VTK %s, SMP %s." % (
        context.get("cpu_model", "processor not recorded"), context.get("num_cpus", "?"), context.get("mhz_per_cpu", "?"),
        caches or "caches not reported",
        " ".join("%.2f" % x for x in context.get("load_avg", [])), context.get("sparse_cholesky", "?"),
        context.get("vtk_version", "?"), context.get("vtk_smp_backend", "?")))
    lines.append("Real time; median of the repetitions, spread min-max over them.")
    families = collections.OrderedDict()
    for name, reps in runs.items():
        families.setdefault(name.split("/")[0], []).append((name, reps))
    for family, members in families.items():
        counters = []
        for _, reps in members:
            for key in reps[0]:
                if key not in STANDARD and key not in counters and isinstance(reps[0][key], (int, float)):
                    counters.append(key)
        lines.append("")
        lines.append("### %s" % family)
        lines.append("")
        lines.append("| benchmark | median | spread | runs | iterations |" + "".join(" %s |" % c for c in counters))
        lines.append("|---|---|---|---|---|" + "---|" * len(counters))
        for name, reps in members:
            errors = [r for r in reps if r.get("error_occurred")]
            if errors:
                lines.append("| `%s` | error: %s | | | |%s" % (name, errors[0].get("error_message", ""), " |" * len(counters)))
                continue
            times = [milliseconds(r["real_time"], r["time_unit"]) for r in reps]
            median = statistics.median(times)
            spread = "%.0f%%" % (100.0 * (max(times) - min(times)) / median) if len(times) > 1 and median > 0 else ""
            # The arguments only: the minimum time and the real-time flag are the same for all.
            arguments = "/".join(part for part in name.split("/")[1:]
                                 if part != "real_time" and not part.startswith("min_time:"))
            row = "| `%s` | %s | %s | %d | %s |" % (
                arguments or family, format_time(median), spread, len(times),
                format_counter(statistics.median(r["iterations"] for r in reps)))
            for c in counters:
                values = [r[c] for r in reps if c in r]
                row += " %s |" % (format_counter(statistics.median(values)) if values else "")
            lines.append(row)
    return lines


HEADER = ["# Benchmark log", "",
          "Generated by `Utilities/benchmark-log.py` from the JSON output of `KerfBenchmarks`; do not",
          "edit by hand. The pages in [filters](filters/) cite these benchmarks by name.", ""]


def main(argv):
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("runs", nargs="+", help="JSON files written by KerfBenchmarks --benchmark_out")
    parser.add_argument("-o", "--output", default="-", help="the Markdown log (default: standard output)")
    parser.add_argument("-a", "--append", action="store_true",
                        help="keep the log's sections and add those of the runs it does not hold")
    args = parser.parse_args(argv)
    lines = list(HEADER)
    if args.append:
        if args.output == "-":
            parser.error("--append needs the log as -o")
        with open(args.output, encoding="utf-8") as f:
            kept = f.read().rstrip("\n").split("\n")
        if kept[:len(HEADER) - 1] != HEADER[:-1]:
            sys.stderr.write("%s is not a benchmark log written by this script\n" % args.output)
            return 1
        lines = kept + [""]
    for path in args.runs:
        with open(path, encoding="utf-8") as f:
            run = section(json.load(f))
        if run[0] in lines:
            sys.stderr.write("%s: the log holds this run already (%s)\n" % (path, run[0][3:]))
            continue
        lines += run + [""]
    text = "\n".join(lines)
    if args.output == "-":
        sys.stdout.write(text)
    else:
        with open(args.output, "w", encoding="utf-8") as f:
            f.write(text)
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
