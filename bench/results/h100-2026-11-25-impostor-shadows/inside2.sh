#!/usr/bin/env bash
# 1,000,000 in place inside the crowd: each half second's shadow pass against its casters.
set -uo pipefail
bin=$(realpath .devbin); res=/tmp/inside2; out=${OUT:-/tmp/out}; device=NVIDIA
source "$bin/lent_machine.sh"
begin_run inside2 QUIET
for beh in in-place mill; do
run $beh "$bin/crowd-bench" "${device_flag[@]}" --scene stress --counts 1000000 --behaviour $beh --start 20 --impostors on \
  --methods compute --size 1920x1080 --frames 600 --warmup 60 --csv "$res/$beh.csv" --frame-log "$res/$beh-frames.csv"
python3 - "$res/$beh-frames.csv" <<'PY' | tee -a "$res/summary.txt"
import csv, sys
rows = list(csv.DictReader(open(sys.argv[1])))
for r in rows[::30]:
    print("t=%5.1f int %5.2f draw %5.2f raster %5.2f shadow %5.2f | mesh tris %5.2f M, shadow tris %5.2f M, shadow impostors %7s, impostors %7s" % (
        float(r["scene_seconds"]), float(r["interval_ms"]), float(r["gpu_draw_ms"]), float(r["gpu_raster_ms"]), float(r["gpu_shadow_ms"]),
        float(r["triangles"]) / 1e6, float(r["shadow_triangles"]) / 1e6, r["shadow_impostors"], r["impostors"]))
PY
done
tar -czf "$out/inside2.tgz" -C /tmp inside2
