#!/usr/bin/env bash
# Frame by frame, on a lent GPU machine: where a p95 comes from. crowd-bench --frame-log on the frames
# whose p95 stands far from their median (issue 18): stress 10,000,000 from above and inside, and
# 1,000,000 milling inside and from above beside the same crowd in place (no planning) on the same
# camera path. Writes each run's frame log and summary CSV into $OUT/frame-log.tgz (one file, as a lent
# machine returns a few); bench/frame_log_summary.py reads them.
#
# Expects the Vulkan loader packages in .gl/ and crowd-bench in .devbin/ (carried).
#   on the H100:      bash bench/run_frame_log.sh
#   here on lavapipe: DEVICE= FRAMES=12 WARMUP=2 SIZE=320x180 BIG=8000 MILL=4000 CAPACITY=1000 bash bench/run_frame_log.sh
# FRAMES (default 600) and WARMUP (60) as crowd-bench's; DEVICE (NVIDIA): part of the device's name,
# empty for the first device; SIZE (1920x1080); BIG (10000000) and MILL (1000000): the two crowds;
# CAPACITY (65536): --mesh-capacity; RUNS: the names of the runs to make (default all six); BIN: the
# folder of the crowd-bench to measure (default .devbin); TAG: a suffix of the results' names, for
# two builds in one session; FLAGS: more crowd-bench flags for every run (e.g. "--threads 14").
set -uo pipefail
source "$(dirname "${BASH_SOURCE[0]}")/lent_machine.sh"
frames=${FRAMES:-600}
warmup=${WARMUP:-60}
device=${DEVICE-NVIDIA}
size=${SIZE:-1920x1080}
big=${BIG:-10000000}
mill=${MILL:-1000000}
capacity=${CAPACITY:-65536}
runs=${RUNS:-big-above big-inside mill-inside in-place-inside mill-above in-place-above}
bin=${BIN:-$PWD/.devbin}
res=/tmp/frame-log${TAG:+-$TAG}
out=${OUT:-/tmp/out}
probe() { "$bin/crowd-bench" "${device_flag[@]}" --quick --methods compute --models soldier --counts 1 \
            --csv "$res/probe.csv" >"$res/probe.txt" 2>&1; }
begin_run run_frame_log

failures=0
for config in "big-above:$big:in-place:0" "big-inside:$big:in-place:20" \
              "mill-inside:$mill:mill:20" "in-place-inside:$mill:in-place:20" \
              "mill-above:$mill:mill:30" "in-place-above:$mill:in-place:30"; do
  IFS=: read -r name count behaviour start <<<"$config"
  [[ " $runs " == *" $name "* ]] || continue
  run "$name" "$bin/crowd-bench" "${device_flag[@]}" --scene stress --counts "$count" --models soldier \
    --behaviour "$behaviour" --start "$start" --impostors on --mesh-capacity "$capacity" --methods compute \
    --frames "$frames" --warmup "$warmup" --size "$size" ${FLAGS:-} --csv "$res/$name.csv" --frame-log "$res/$name-frames.csv" &&
    printf '%-16s median %8.3f ms  p95 %8.3f ms\n' "$name" "$(csv_value "$res/$name.csv" median_frame_ms)" \
      "$(csv_value "$res/$name.csv" p95_frame_ms)"
done
tar -czf "$out/frame-log${TAG:+-$TAG}.tgz" -C "$(dirname "$res")" "$(basename "$res")"
exit $((failures > 0))
