#!/usr/bin/env bash
# What the impostor blend costs now that it blends the elevation bands too (issue 19; up to eight atlas
# cells a pixel where it blended four), on a lent GPU machine: crowd-bench on stress 1,000,000 from above
# (t = 0, every soldier an impostor), --impostors on, method compute, 1920x1080, with the impostors
# rasterized in compute (--raster compute: the compute rasterizer's coverage test and its resolve) and by
# the graphics pipeline (--raster hardware), each with --impostor-blend on and off (off: the nearest cell,
# one fetch, as before the blend). Twice, interleaved so drift shows. Prints every pass's GPU time
# (medians) and the change against blend off in the same build, rasterizer and round; writes
# $OUT/elevation-blend.tgz (every run's output and CSV).
#
# Builds: BINS (".devbin"), folders each holding crowd-bench with its shared libraries. To time the
# elevation bands' share alone, carry a build of the commit before them (the branch's base) as
# .devbin-bands and give BINS=".devbin-bands .devbin": its blend on is the four-cell blend.
# Expects the Vulkan loader packages in .gl/ (carried).
#   on the H100:      bash bench/run_elevation_blend.sh
#   here on lavapipe: DEVICE= COUNT=8000 SIZE=480x270 FRAMES=3 WARMUP=1 bash bench/run_elevation_blend.sh
# FRAMES (default 300) and WARMUP (30): crowd-bench's --frames and --warmup; COUNT (1000000); SIZE
# (1920x1080); DEVICE (NVIDIA): part of the device's name, empty for the first device.
set -uo pipefail
source "$(dirname "${BASH_SOURCE[0]}")/lent_machine.sh"
frames=${FRAMES:-300}
warmup=${WARMUP:-30}
count=${COUNT:-1000000}
size=${SIZE:-1920x1080}
device=${DEVICE-NVIDIA}
read -r -a bins <<<"${BINS:-.devbin}"
bin=$PWD/${bins[0]}
res=/tmp/elevation-blend
out=${OUT:-/tmp/out}
probe() { "$bin/crowd-bench" "${device_flag[@]}" --counts 1 --frames 1 --warmup 0 --size 64x64 >"$res/probe.txt" 2>&1; }
begin_run run_elevation_blend

failures=0
rasters="compute hardware"
blends="off on"
for round in 1 2; do
  for b in "${!bins[@]}"; do
    for raster in $rasters; do
      for blend in $blends; do
        key=$b-$raster-$blend-$round
        LD_LIBRARY_PATH=$PWD/${bins[$b]}:$LD_LIBRARY_PATH run "bench-$key" "$PWD/${bins[$b]}/crowd-bench" "${device_flag[@]}" \
          --scene stress --counts "$count" --start 0 --impostors on --impostor-blend "$blend" --raster "$raster" \
          --methods compute --size "$size" --frames "$frames" --warmup "$warmup" --csv "$res/bench-$key.csv"
      done
    done
  done
done

# Percent by which $2 is over $1.
percent() { awk -v a="$1" -v b="$2" 'BEGIN { if (a + 0 > 0 && b != "") printf "%+.1f%%", 100 * (b - a) / a; else print "-" }'; }
passes="gpu_total_ms gpu_cull_ms gpu_shadow_ms gpu_raster_ms gpu_draw_ms"
{
  echo
  echo "stress $count from above (t = 0), --impostors on, compute, $size; crowd-bench medians over $frames frames"
  echo "after $warmup warm-up, ms; frame: wall clock between frame starts; gpu: every pass; cull, shadow, raster (the"
  echo "compute rasterizer, impostors and meshes), draw (the colour pass: ground, meshes, hardware impostors, the"
  echo "compute impostors' resolve); +%: against --impostor-blend off of the same build, rasterizer and round"
  echo "($(csv_value "$res/bench-0-compute-off-1.csv" pass_clock))"
  printf "%-14s %-8s %-5s %1s | %8s" build raster blend r frame
  for p in $passes; do p=${p#gpu_}; printf " | %8s %7s" "${p%_ms}" "+%"; done
  echo
  for round in 1 2; do
    for b in "${!bins[@]}"; do
      for raster in $rasters; do
        base=$res/bench-$b-$raster-off-$round.csv
        for blend in $blends; do
          csv=$res/bench-$b-$raster-$blend-$round.csv
          if [[ $(csv_value "$csv" status) != ok ]]; then
            printf "%-14s %-8s %-5s %1s | %8s\n" "${bins[$b]}" "$raster" "$blend" "$round" failed
            continue
          fi
          printf "%-14s %-8s %-5s %1s | %8.3f" "${bins[$b]}" "$raster" "$blend" "$round" "$(csv_value "$csv" median_frame_ms)"
          for p in $passes; do
            printf " | %8.3f %7s" "$(csv_value "$csv" "$p")" "$(percent "$(csv_value "$base" "$p")" "$(csv_value "$csv" "$p")")"
          done
          echo
        done
      done
    done
  done
} | tee "$res/summary.txt"
tar -czf "$out/elevation-blend.tgz" -C /tmp elevation-blend
[[ $failures == 0 ]] || { echo "run_elevation_blend: $failures run(s) failed (see their .txt in elevation-blend.tgz)"; exit 1; }
