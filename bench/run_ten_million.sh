#!/usr/bin/env bash
# Issue 18 on a lent GPU machine: the stress scene with impostors and shadows on at 1, 2, 4 and 10
# million soldiers, from above (t = 0 s) and inside the crowd (--start 20), bone blocks per mesh slot
# (the default mesh capacity, 65,536). crowd-bench, `compute` by default; prints per run the median and
# 95th-percentile frame, fps, every pass's GPU time, the characters drawn per level, and the device
# memory the renderer allocated (total, per character, and the bytes per character that grow with the
# crowd: records, motion segments, lists); writes $OUT/ten-million.tgz (every run's output, CSV, JSON).
#
# Expects the Vulkan loader packages in .gl/ and crowd-bench (and its shared libraries) in .devbin/.
#   on the H100:      bash bench/run_ten_million.sh
#   here on lavapipe: DEVICE= COUNTS="2000 4000" FRAMES=3 WARMUP=1 SIZE=480x270 MESH_CAPACITY=1000 bash bench/run_ten_million.sh
# COUNTS (default "1000000 2000000 4000000 10000000"); FRAMES (60) and WARMUP (10) as crowd-bench's
# --frames and --warmup; SIZE (1920x1080); METHOD (compute); MESH_CAPACITY (65536; lavapipe's 128 MiB
# storage-buffer range takes about 10,000 soldiers' skinned vertices); DEVICE (NVIDIA): part of the
# device's name, empty for the first device.
set -uo pipefail
source "$(dirname "${BASH_SOURCE[0]}")/lent_machine.sh"
counts=${COUNTS:-1000000 2000000 4000000 10000000}
frames=${FRAMES:-60}
warmup=${WARMUP:-10}
size=${SIZE:-1920x1080}
method=${METHOD:-compute}
capacity=${MESH_CAPACITY:-65536}
device=${DEVICE-NVIDIA}
bin=$PWD/.devbin
res=/tmp/ten-million
out=${OUT:-/tmp/out}
probe() { "$bin/crowd-bench" "${device_flag[@]}" --quick --methods compute --models soldier --counts 1 \
            --csv "$res/probe.csv" >"$res/probe.txt" 2>&1; }
begin_run run_ten_million

failures=0
cameras="above inside"
start_of() { [[ $1 == above ]] && echo 0 || echo 20; }

for count in $counts; do
  for camera in $cameras; do
    key=$count-$camera
    run "bench-$key" "$bin/crowd-bench" "${device_flag[@]}" --scene stress --counts "$count" --models soldier \
      --start "$(start_of "$camera")" --impostors on --mesh-capacity "$capacity" --shadows on --methods "$method" \
      --frames "$frames" --warmup "$warmup" --size "$size" --csv "$res/bench-$key.csv" --json "$res/bench-$key.json"
  done
done

# A number from crowd-bench's JSON of one run (pretty-printed, one key a line).
json_value() { grep -o "\"$2\": [0-9.e+-]*" "$1" 2>/dev/null | head -1 | awk '{ print $2 }'; }
gib() { awk -v b="$1" 'BEGIN { if (b == "") print "-"; else printf "%.3f", b / 1073741824 }'; }

{
  echo
  echo "stress, $method, impostors on, --mesh-capacity $capacity, shadows on, $size; medians over $frames frames"
  echo "after $warmup warm-up, ms; frame: wall clock between frame starts (two frames in flight); passes: GPU time"
  echo "($(csv_value "$res/bench-$(echo "$counts" | awk '{ print $1 }')-above.csv" pass_clock)). meshes: LOD 0/1/2; memory: what the renderer allocated;"
  echo "B/char: that over the count; grows: the state per character (records, motion, lists; bytes) from the JSON."
  printf "%-9s %-7s | %8s %8s %6s | %6s %6s %6s %6s %6s %7s %7s | %-17s %9s | %8s %7s %7s\n" soldiers camera \
    median p95 fps motion cull palette skin shadow draw total meshes impostors "mem GiB" B/char grows
  for count in $counts; do
    for camera in $cameras; do
      key=$count-$camera
      csv=$res/bench-$key.csv
      json=$res/bench-$key.json
      if [[ $(csv_value "$csv" status) != ok ]]; then
        printf "%-9s %-7s | %s\n" "$count" "$camera" "not run: $(tail -1 "$res/bench-$key.txt")"
        continue
      fi
      memory=$(csv_value "$csv" memory_bytes)
      printf "%-9s %-7s | %8.3f %8.3f %6.1f | %6.3f %6.3f %6.3f %6.3f %6.3f %7.3f %7.3f | %-17s %9s | %8s %7.1f %7.1f\n" \
        "$count" "$camera" "$(csv_value "$csv" median_frame_ms)" "$(csv_value "$csv" p95_frame_ms)" \
        "$(csv_value "$csv" fps)" "$(csv_value "$csv" gpu_motion_ms)" "$(csv_value "$csv" gpu_cull_ms)" \
        "$(csv_value "$csv" gpu_palette_ms)" "$(csv_value "$csv" gpu_skin_ms)" "$(csv_value "$csv" gpu_shadow_ms)" \
        "$(csv_value "$csv" gpu_draw_ms)" "$(csv_value "$csv" gpu_total_ms)" \
        "$(csv_value "$csv" visible_lod0)/$(csv_value "$csv" visible_lod1)/$(csv_value "$csv" visible_lod2)" \
        "$(json_value "$json" median_impostors)" "$(gib "$memory")" \
        "$(awk -v m="$memory" -v n="$count" 'BEGIN { print m / n }')" "$(json_value "$json" state)"
    done
  done
} | tee "$res/summary.txt"
tar -czf "$out/ten-million.tgz" -C /tmp ten-million
[[ $failures == 0 ]] || { echo "run_ten_million: $failures run(s) failed (see their .txt in ten-million.tgz)"; exit 1; }
