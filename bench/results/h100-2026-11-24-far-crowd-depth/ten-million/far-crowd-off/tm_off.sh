#!/usr/bin/env bash
# 10,000,000 and 1,000,000 with --far-crowd off (same binaries as run_ten_million.sh's default run).
set -uo pipefail
source .devbin/lent_machine.sh
bin=$PWD/.devbin; res=/tmp/tm-off; out=${OUT:-/tmp/out}; device=NVIDIA
begin_run tm_off
failures=0
for count in 1000000 10000000; do for start in 0 20; do
  run "off-$count-$start" "$bin/crowd-bench" "${device_flag[@]}" --scene stress --counts $count --models soldier --start $start --impostors on --mesh-capacity 65536 --shadows on --methods compute --far-crowd off --frames 60 --warmup 10 --size 1920x1080 --csv "$res/off-$count-$start.csv"
  echo "$count start $start far-crowd off: frame $(csv_value "$res/off-$count-$start.csv" median_frame_ms) p95 $(csv_value "$res/off-$count-$start.csv" p95_frame_ms) raster $(csv_value "$res/off-$count-$start.csv" gpu_raster_ms) draw $(csv_value "$res/off-$count-$start.csv" gpu_draw_ms) memory $(csv_value "$res/off-$count-$start.csv" memory_bytes)" | tee -a "$res/summary.txt"
done; done
tar -czf "$out/tm-off.tgz" -C /tmp tm-off
