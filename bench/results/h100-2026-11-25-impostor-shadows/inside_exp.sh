#!/usr/bin/env bash
# The milling 1,000,000 inside the crowd: the mesh path by auto's gate (4 M triangles) against always on
# (--mesh-raster-limit 64); frame logs binned by second of scene time.
set -uo pipefail
bin=$(realpath .devbin); res=/tmp/inside; out=${OUT:-/tmp/out}; device=NVIDIA
source "$bin/lent_machine.sh"
begin_run inside_exp QUIET
for r in 1 2; do for beh in mill in-place; do for lim in auto 64; do
  key=$beh-$lim-$r
  run "$key" "$bin/crowd-bench" "${device_flag[@]}" --scene stress --counts 1000000 --behaviour $beh --start 20 --impostors on \
    --mesh-raster-limit $lim --methods compute --size 1920x1080 --frames 600 --warmup 60 --csv "$res/$key.csv" --frame-log "$res/$key-frames.csv"
  printf "%-18s | frame %7.3f p95 %7.3f ratio %s\n" "$key" "$(csv_value "$res/$key.csv" median_frame_ms)" "$(csv_value "$res/$key.csv" p95_frame_ms)" \
    "$(awk -v a="$(csv_value "$res/$key.csv" median_frame_ms)" -v b="$(csv_value "$res/$key.csv" p95_frame_ms)" 'BEGIN{printf "%.2f", b/a}')" | tee -a "$res/summary.txt"
  python3 - "$res/$key-frames.csv" <<'PY' | tee -a "$res/summary.txt"
import csv, sys, statistics
rows = list(csv.DictReader(open(sys.argv[1])))
bins = {}
for r in rows:
    bins.setdefault(int(float(r["scene_seconds"])), []).append(r)
for s in sorted(bins):
    b = bins[s]
    print("   t=%2d s  interval %6.2f ms  gpu %6.2f ms  plan %5.2f  tris %5.2f M" % (s, statistics.median(float(x["interval_ms"]) for x in b),
          statistics.median(float(x["gpu_total_ms"]) for x in b), statistics.median(float(x["cpu_plan_ms"]) for x in b),
          statistics.median(float(x["triangles"]) for x in b) / 1e6))
PY
done; done; done
tar -czf "$out/inside.tgz" -C /tmp inside
