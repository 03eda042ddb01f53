#!/usr/bin/python3
"""Turns a crowd-bench CSV into the Markdown tables docs/results.md shows: fps per method and crowd size
(the paper's Table 1 layout), each method's frame time relative to `static`, and the passes at one size.
Usage: bench/table.py RESULTS.csv [CHARACTERS_FOR_PASSES]"""
import csv
import sys
from collections import defaultdict


def main():
    if len(sys.argv) < 2:
        sys.exit(__doc__)
    rows = [r for r in csv.DictReader(open(sys.argv[1], newline="")) if r["status"] == "ok"]
    pass_count = sys.argv[2] if len(sys.argv) > 2 else "4096"
    methods = list(dict.fromkeys(r["method"] for r in rows))
    models = list(dict.fromkeys(r["model"] for r in rows))
    by = {(r["model"], r["method"], r["characters"]): r for r in rows}
    counts = sorted({int(r["characters"]) for r in rows})
    for model in models:
        print(f"**{model}: fps** (median; in brackets: frame time / `static`)\n")
        print("| characters | " + " | ".join(methods) + " |")
        print("|---:|" + "---:|" * len(methods))
        for count in counts:
            cells = []
            for method in methods:
                r = by.get((model, method, str(count)))
                cells.append(f"{float(r['fps']):.0f} ({float(r['ratio_to_static']):.2f})" if r else "-")
            print(f"| {count:,} | " + " | ".join(cells) + " |")
        print()
    print(f"**GPU ms per pass at {int(pass_count):,} characters** (median; clock: "
          f"{rows[0]['pass_clock']}; Gvert/s = skinned vertices per second of the skin pass)\n")
    print("| model | method | frame ms | upload | skin | copy | draw | Gvert/s | CPU animate ms |")
    print("|---|---|---:|---:|---:|---:|---:|---:|---:|")
    for model in models:
        for method in methods:
            r = by.get((model, method, pass_count))
            if not r:
                continue
            print(f"| {model} | {method} | {float(r['median_frame_ms']):.2f} | {float(r['gpu_upload_ms']):.3f} | "
                  f"{float(r['gpu_skin_ms']):.3f} | {float(r['gpu_copy_ms']):.3f} | {float(r['gpu_draw_ms']):.3f} | "
                  f"{float(r['skin_vertices_per_s']) / 1e9:.2f} | {float(r['cpu_animate_ms']):.2f} |")


if __name__ == "__main__":
    main()
