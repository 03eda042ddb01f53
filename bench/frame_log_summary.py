#!/usr/bin/env python3
"""Summarizes crowd-bench --frame-log files (bench/run_frame_log.sh): where a p95 comes from.

For each log: the frames' median and p95 (as crowd-bench reports them) and their ratio, then the
*local* ratio: each frame's interval over the median of the 31 frames centred on it (half a second of
scene time). A camera path that changes what is in view moves the median along the run, so the global
p95 over the median measures the path as much as any hitch; the local ratio measures the hitches: a
frame slower than the frames around it. Given pairs NAME=OTHER (a milling crowd and the same crowd in
place on the same path), also the per-frame difference of their intervals: what planning adds, frame
by frame.

usage: frame_log_summary.py DIR [NAME=OTHER ...]   (DIR holds NAME-frames.csv files)
"""
import csv
import pathlib
import statistics
import sys

WINDOW = 31


def percentile(values, fraction):
    """crowd-bench's percentile: the value at rank fraction x (n - 1), interpolated."""
    ordered = sorted(values)
    rank = fraction * (len(ordered) - 1)
    low = int(rank)
    high = min(low + 1, len(ordered) - 1)
    return ordered[low] + (ordered[high] - ordered[low]) * (rank - low)


def intervals(path):
    with open(path, newline="") as file:
        return [float(row["interval_ms"]) for row in csv.DictReader(file)]


def local_ratios(values):
    half = WINDOW // 2
    ratios = []
    for i, value in enumerate(values):
        window = values[max(0, i - half): i + half + 1]
        ratios.append(value / statistics.median(window))
    return ratios


def main():
    if len(sys.argv) < 2:
        sys.exit(__doc__)
    folder = pathlib.Path(sys.argv[1])
    logs = {path.name[: -len("-frames.csv")]: intervals(path) for path in sorted(folder.glob("*-frames.csv"))}
    print(f"{'run':<18} {'frames':>6} {'median':>8} {'p95':>8} {'p95/med':>8} | {'local p95':>9} {'local max':>9}")
    for name, values in logs.items():
        median, p95 = statistics.median(values), percentile(values, 0.95)
        local = local_ratios(values)
        print(f"{name:<18} {len(values):>6} {median:>8.3f} {p95:>8.3f} {p95 / median:>7.2f}x |"
              f" {percentile(local, 0.95):>8.2f}x {max(local):>8.2f}x")
    for pair in sys.argv[2:]:
        name, other = pair.split("=")
        if name not in logs or other not in logs:
            print(f"{pair}: no log for one of them")
            continue
        added = [a - b for a, b in zip(logs[name], logs[other])]
        print(f"{name} - {other}, per frame: median {statistics.median(added):+.3f} ms,"
              f" p95 {percentile(added, 0.95):+.3f} ms, max {max(added):+.3f} ms")


if __name__ == "__main__":
    main()
