#!/usr/bin/python3
"""Plots crowd-bench CSV results: frame time against crowd size, log-log, one line per method,
one panel per model. Uses Debian's python3-matplotlib (run it with /usr/bin/python3).
Usage: bench/plot.py RESULTS.csv OUTPUT.png [TITLE]"""
import csv
import sys
from collections import defaultdict

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402


def load(path):
    rows = defaultdict(lambda: defaultdict(list))  # model -> method -> [(count, ms)]
    device = ""
    with open(path, newline="") as f:
        for row in csv.DictReader(f):
            device = row["device"]
            if row["status"] != "ok":
                continue
            rows[row["model"]][row["method"]].append((int(row["characters"]), float(row["median_frame_ms"])))
    return rows, device


def main():
    if len(sys.argv) < 3:
        sys.exit(__doc__)
    rows, device = load(sys.argv[1])
    title = sys.argv[3] if len(sys.argv) > 3 else device
    models = sorted(rows)
    fig, axes = plt.subplots(1, len(models), figsize=(6.5 * len(models), 5), squeeze=False)
    for axis, model in zip(axes[0], models):
        for method, points in sorted(rows[model].items()):
            points.sort()
            axis.plot([p[0] for p in points], [p[1] for p in points], marker="o", label=method)
        axis.set_xscale("log", base=2)
        axis.set_yscale("log")
        axis.set_xlabel("characters")
        axis.set_ylabel("median frame time (ms)")
        axis.set_title(model)
        axis.grid(True, which="both", alpha=0.3)
        axis.axhline(1000.0 / 60.0, color="gray", linestyle="--", linewidth=1)
        axis.legend(fontsize=8)
    fig.suptitle(title)
    fig.tight_layout()
    fig.savefig(sys.argv[2], dpi=110)


if __name__ == "__main__":
    main()
