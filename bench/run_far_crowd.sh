#!/usr/bin/env bash
# The far crowd averaged (--far-crowd average|off), on a lent GPU machine: stress 1,000,000 from above
# (t = 0) with impostors at 1920x1080, one sample a pixel (--aa off), raster auto, method compute.
# 1. Pictures: crowd-render with --far-crowd average and off, each against the 4x4 supersampled render
#    of the same frame (crowd-render at 4x the width and height, --far-crowd off, box-filtered down in
#    linear light by image-downsample), compared by image-psnr, as bench/run_aa.sh does.
# 2. Cost: crowd-bench with each setting, twice, interleaved so drift shows: median and p95 frame,
#    GPU total, raster pass and colour (draw) pass, against --far-crowd off of the same round.
# Writes $OUT/far-crowd.tgz (every run's output, CSV and picture).
#
# Expects the Vulkan loader packages in .gl/ and crowd-render, crowd-bench, image-psnr and
# image-downsample with their shared libraries in .devbin/ (carried; BIN names another folder).
#   on the H100:      bash bench/run_far_crowd.sh
#   here on lavapipe: DEVICE= BIN=build COUNT=8000 SIZE=480x270 FRAMES=3 WARMUP=1 PICTURE_FRAMES=2 bash bench/run_far_crowd.sh
# FRAMES (default 200) and WARMUP (20) as crowd-bench's --frames and --warmup; PICTURE_FRAMES (30):
# crowd-render's --frames (the picture is the last frame's); DEVICE (NVIDIA): part of the device's
# name, empty for the first device; SIZE (1920x1080, the supersampled render at 4x); COUNT (1000000;
# lavapipe's 128 MiB storage-buffer range takes 8000 with compute).
set -uo pipefail
source "$(dirname "${BASH_SOURCE[0]}")/lent_machine.sh"
frames=${FRAMES:-200}
warmup=${WARMUP:-20}
picture_frames=${PICTURE_FRAMES:-30}
device=${DEVICE-NVIDIA}
size=${SIZE:-1920x1080}
count=${COUNT:-1000000}
bin=$(realpath "${BIN:-.devbin}")
res=/tmp/far-crowd
out=${OUT:-/tmp/out}
begin_run run_far_crowd

failures=0
width=${size%x*}
height=${size#*x}
big_size=$((width * 4))x$((height * 4))
scene=(--scene stress --count "$count" --start 0 --impostors on --method compute --aa off)

# Percent by which $2 is over $1.
percent() { awk -v a="$1" -v b="$2" 'BEGIN { if (a + 0 > 0 && b != "") printf "%+.1f%%", 100 * (b - a) / a; else print "-" }'; }

# 1. Pictures.
run supersampled-4x "$bin/crowd-render" "${device_flag[@]}" "${scene[@]}" --far-crowd off --frames "$picture_frames" \
  --size "$big_size" --out "$res/supersampled-4x.png" &&
  run supersampled "$bin/image-downsample" "$res/supersampled-4x.png" 4 "$res/supersampled.png"
for setting in average off; do
  run "picture-$setting" "$bin/crowd-render" "${device_flag[@]}" "${scene[@]}" --far-crowd "$setting" \
    --frames "$picture_frames" --size "$size" --out "$res/picture-$setting.png" &&
    "$bin/image-psnr" "$res/supersampled.png" "$res/picture-$setting.png" >"$res/picture-$setting.psnr" 2>&1
done
rm -f "$res/supersampled-4x.png"  # 4x the pixels: kept out of the archive

# 2. Cost, two interleaved rounds.
for round in 1 2; do
  for setting in off average; do
    run "bench-$setting-$round" "$bin/crowd-bench" "${device_flag[@]}" --scene stress --counts "$count" --start 0 \
      --impostors on --methods compute --aa off --far-crowd "$setting" --frames "$frames" --warmup "$warmup" \
      --size "$size" --csv "$res/bench-$setting-$round.csv"
  done
done

{
  echo
  echo "stress $count from above (t = 0), impostors, compute, raster auto, --aa off, $size"
  echo "PSNR against the 4x4 supersampled render ($big_size, --far-crowd off, box-filtered down):"
  for setting in average off; do
    printf "  --far-crowd %-7s %s\n" "$setting" "$(head -1 "$res/picture-$setting.psnr" 2>/dev/null || echo failed)"
  done
  echo
  echo "crowd-bench over $frames frames after $warmup warm-up, ms; frame: wall clock between frame starts;"
  echo "gpu: every pass's GPU time; raster: the compute rasterizer's pass; draw: the colour pass (with the"
  echo "resolves) ($(csv_value "$res/bench-off-1.csv" pass_clock)); %: against --far-crowd off of the same round"
  printf "%-8s %1s | %8s %8s %8s | %8s %8s | %8s %8s | %8s %8s\n" setting r frame p95 "vs off" gpu "vs off" \
    raster "vs off" draw "vs off"
  for round in 1 2; do
    base=$res/bench-off-$round.csv
    for setting in off average; do
      csv=$res/bench-$setting-$round.csv
      if [[ $(csv_value "$csv" status) != ok ]]; then
        printf "%-8s %1s | %8s\n" "$setting" "$round" skipped
        continue
      fi
      printf "%-8s %1s | %8.3f %8.3f %8s | %8.3f %8s | %8.3f %8s | %8.3f %8s\n" "$setting" "$round" \
        "$(csv_value "$csv" median_frame_ms)" "$(csv_value "$csv" p95_frame_ms)" \
        "$(percent "$(csv_value "$base" median_frame_ms)" "$(csv_value "$csv" median_frame_ms)")" \
        "$(csv_value "$csv" gpu_total_ms)" "$(percent "$(csv_value "$base" gpu_total_ms)" "$(csv_value "$csv" gpu_total_ms)")" \
        "$(csv_value "$csv" gpu_raster_ms)" "$(percent "$(csv_value "$base" gpu_raster_ms)" "$(csv_value "$csv" gpu_raster_ms)")" \
        "$(csv_value "$csv" gpu_draw_ms)" "$(percent "$(csv_value "$base" gpu_draw_ms)" "$(csv_value "$csv" gpu_draw_ms)")"
    done
  done
} | tee "$res/summary.txt"
tar -czf "$out/far-crowd.tgz" -C /tmp far-crowd
[[ $failures == 0 ]] || { echo "run_far_crowd: $failures run(s) failed (see their .txt in far-crowd.tgz)"; exit 1; }
