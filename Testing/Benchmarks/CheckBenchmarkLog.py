"""Utilities/benchmark-log.py turns a KerfBenchmarks run into the log: a short run with two
repetitions gives a section for its family whose row holds the median of the repetitions; with
--append a later run adds its section after the log's, which stay as they were, and a run the log
holds already adds nothing.

Usage: CheckBenchmarkLog.py KERF_BENCHMARKS SOURCE_DIR WORK_DIR"""
import json
import os
import statistics
import subprocess
import sys


def main(program, source, work):
    os.makedirs(work, exist_ok=True)
    run = os.path.join(work, "benchmark-log-run.json")
    log = os.path.join(work, "benchmark-log.md")
    subprocess.run([program, "--benchmark_filter=BM_SketchStroke", "--benchmark_min_time=0.01",
                    "--benchmark_repetitions=2", "--benchmark_out=" + run, "--benchmark_out_format=json"],
                   check=True, stdout=subprocess.DEVNULL)
    subprocess.run([sys.executable, os.path.join(source, "Utilities", "benchmark-log.py"), run, "-o", log],
                   check=True)
    with open(run, encoding="utf-8") as f:
        repetitions = [b for b in json.load(f)["benchmarks"] if b["run_type"] == "iteration"]
    with open(log, encoding="utf-8") as f:
        text = f.read()
    failures = []
    if len(repetitions) != 2:
        failures.append("the run has %d repetitions, not 2" % len(repetitions))
    if "### BM_SketchStroke" not in text:
        failures.append("the log has no section for BM_SketchStroke")
    median_us = statistics.median(b["real_time"] for b in repetitions) * 1000.0  # ms -> us
    row = [line for line in text.split("\n") if line.startswith("| `1300x770`")]
    if len(row) != 1:
        failures.append("the log has %d rows for 1300x770, not 1" % len(row))
    elif "%.3g us" % median_us not in row[0] or "| 2 |" not in row[0]:
        failures.append("the row %r lacks the median %.3g us of 2 runs" % (row[0], median_us))
    # A later run (the same figures under a later date) appended, then appended again.
    with open(run, encoding="utf-8") as f:
        later = json.load(f)
    later["context"]["date"] = "2999-01-01T00:00:00+00:00"
    later_run = os.path.join(work, "benchmark-log-later.json")
    with open(later_run, "w", encoding="utf-8") as f:
        json.dump(later, f)
    script = [sys.executable, os.path.join(source, "Utilities", "benchmark-log.py"), "--append"]
    subprocess.run(script + [later_run, "-o", log], check=True)
    with open(log, encoding="utf-8") as f:
        appended = f.read()
    subprocess.run(script + [later_run, run, "-o", log], check=True, stderr=subprocess.DEVNULL)
    with open(log, encoding="utf-8") as f:
        again = f.read()
    if not appended.startswith(text) or appended.count("## Run of ") != 2 or "## Run of 2999-01-01" not in appended:
        failures.append("--append did not keep the first run's section and add the later one after it")
    if again != appended:
        failures.append("--append with runs the log holds changed it")
    for failure in failures:
        print("ERROR: " + failure)
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main(*sys.argv[1:]))
