#!/usr/bin/env bash
# Small characters' meshes in the compute rasterizer (docs/compute-raster.md, "Meshes") against the
# hardware rasterizer, on a lent GPU machine:
#  1. the crossover: the stress scene from high above (t = 0 s) at SIZE, every character a mesh (impostors
#     off), shadows off, for crowds from SWEEP_COUNTS: the fewer the characters, the larger each on screen
#     (the crowd fills the view). Per row, each path's GPU time for the meshes (hardware: the draw pass;
#     compute: the raster pass plus the draw pass, which holds the resolve; both hold the ground) and
#     triangles per second; the crossover is the size where compute's time passes the hardware's.
#  2. the issue's frame: ISSUE_COUNT soldiers inside the crowd (t = 20 s) at ISSUE_SIZE, every one a mesh,
#     shadows on, with --raster hardware, compute, and auto at each of LIMITS (--mesh-raster-limit).
#  3. pictures: crowd-render's frame of section 2 with each rasterizer, and image-psnr against hardware.
# Prints the tables and writes $OUT/mesh-raster.tgz (every run's output, the CSVs, the pictures).
#
# Expects the Vulkan loader packages in .gl/ and crowd-bench, crowd-render and image-psnr in .devbin/
# (carried; BIN names another folder).
#   on the H100:      bash bench/run_mesh_raster.sh
#   here on lavapipe: DEVICE= BIN=build FRAMES=3 WARMUP=1 SIZE=480x270 ISSUE_SIZE=480x270 \
#                     SWEEP_COUNTS="3000 300" ISSUE_COUNT=3000 LIMITS="16 48" bash bench/run_mesh_raster.sh
# FRAMES (default 60) and WARMUP (10) as crowd-bench's --frames and --warmup; DEVICE (NVIDIA): part of the
# device's name, empty for the first device; SIZE (1920x1080); SWEEP_COUNTS (250000 62500 15625 3906 977
# 244); ISSUE_SIZE (1920x1080); ISSUE_COUNT (250000); LIMITS (16 32 64 128); SECTIONS ("1 2 3").
set -uo pipefail
source "$(dirname "${BASH_SOURCE[0]}")/lent_machine.sh"
frames=${FRAMES:-60}
warmup=${WARMUP:-10}
device=${DEVICE-NVIDIA}
size=${SIZE:-1920x1080}
issue_size=${ISSUE_SIZE:-1920x1080}
issue_count=${ISSUE_COUNT:-250000}
read -r -a sweep_counts <<<"${SWEEP_COUNTS:-250000 62500 15625 3906 977 244}"
read -r -a limits <<<"${LIMITS:-16 32 64 128}"
bin=$(realpath "${BIN:-.devbin}")
res=/tmp/mesh-raster
out=${OUT:-/tmp/out}
begin_run run_mesh_raster
mkdir -p "$res/pictures"

failures=0
sections=" ${SECTIONS:-1 2 3} "
section() { [[ $sections == *" $1 "* ]]; }
every_mesh=(--impostors off)
# The issue's frame's variants: name and flags.
variants=("hardware:--raster hardware" "compute:--raster compute")
for limit in "${limits[@]}"; do variants+=("auto-$limit:--raster auto --mesh-raster-limit $limit"); done

section 1 && for count in "${sweep_counts[@]}"; do
  for raster in hardware compute; do
    run "sweep-$count-$raster" "$bin/crowd-bench" "${device_flag[@]}" --scene stress --counts "$count" --methods compute \
      "${every_mesh[@]}" --shadows off --raster $raster --frames "$frames" --warmup "$warmup" --size "$size" \
      --csv "$res/sweep-$count-$raster.csv"
  done
done
section 2 && for variant in "${variants[@]}"; do
  name=${variant%%:*}
  read -r -a flags <<<"${variant#*:}"
  run "issue-$name" "$bin/crowd-bench" "${device_flag[@]}" --scene stress --counts "$issue_count" --start 20 \
    --methods compute "${every_mesh[@]}" "${flags[@]}" --frames "$frames" --warmup "$warmup" --size "$issue_size" \
    --csv "$res/issue-$name.csv"
done
section 3 && for variant in "${variants[@]}"; do
  name=${variant%%:*}
  read -r -a flags <<<"${variant#*:}"
  run "picture-$name" "$bin/crowd-render" "${device_flag[@]}" --scene stress --count "$issue_count" --start 20 \
    --method compute "${every_mesh[@]}" "${flags[@]}" --frames 3 --size "$issue_size" \
    --out "$res/pictures/stress-$issue_count-t20-$name.png"
done

ok() { [[ $(csv_value "$1" status) == ok ]]; }
{
  section 1 && {
  echo
  echo "1. Meshes, stress from above at $size, every character a mesh, shadows off; medians over $frames frames"
  echo "after $warmup warm-up ($(csv_value "$res/sweep-${sweep_counts[0]}-hardware.csv" pass_clock)). px/char: screen pixels"
  echo "per character (the crowd fills the view); hw: the draw pass; cs: raster + draw (the resolve); both hold"
  echo "the ground. G tri/s: triangles drawn per second of that time; cs/hw: compute's time over hardware's."
  printf "%10s %10s %8s | %9s %9s | %9s %9s %9s | %7s\n" characters triangles px/char "hw ms" "G tri/s" "raster" \
    "cs draw" "G tri/s" "cs/hw"
  for count in "${sweep_counts[@]}"; do
    hw=$res/sweep-$count-hardware.csv cs=$res/sweep-$count-compute.csv
    if ! ok "$hw" || ! ok "$cs"; then printf "%10s skipped\n" "$count"; continue; fi
    awk -v n="$count" -v t="$(csv_value "$hw" triangles_drawn)" -v w="$(csv_value "$hw" width)" -v h="$(csv_value "$hw" height)" \
      -v hd="$(csv_value "$hw" gpu_draw_ms)" -v cr="$(csv_value "$cs" gpu_raster_ms)" -v cd="$(csv_value "$cs" gpu_draw_ms)" '
      BEGIN {
        cs = cr + cd
        printf "%10d %10d %8.1f | %9.3f %9.2f | %9.3f %9.3f %9.2f | %7.2f\n", n, t, w * h / n, hd,
          (hd > 0 ? t / (hd * 1e6) : 0), cr, cd, (cs > 0 ? t / (cs * 1e6) : 0), (hd > 0 ? cs / hd : 0)
      }'
  done
  }
  section 2 && {
  echo
  echo "2. $issue_count soldiers inside the crowd (t = 20 s) at $issue_size, every one a mesh, shadows on; frame: wall"
  echo "clock between frame starts (two in flight); GPU ms per pass."
  printf "%-10s | %9s %9s %7s | %8s %8s %8s %8s | %10s\n" raster frame p95 fps skin shadow raster draw triangles
  for variant in "${variants[@]}"; do
    name=${variant%%:*} csv=$res/issue-${variant%%:*}.csv
    if ! ok "$csv"; then printf "%-10s | skipped (%s)\n" "$name" "$(tail -1 "$res/issue-$name.txt" | cut -c1-80)"; continue; fi
    printf "%-10s | %9.3f %9.3f %7.1f | %8.3f %8.3f %8.3f %8.3f | %10.0f\n" "$name" "$(csv_value "$csv" median_frame_ms)" \
      "$(csv_value "$csv" p95_frame_ms)" "$(csv_value "$csv" fps)" "$(csv_value "$csv" gpu_skin_ms)" \
      "$(csv_value "$csv" gpu_shadow_ms)" "$(csv_value "$csv" gpu_raster_ms)" "$(csv_value "$csv" gpu_draw_ms)" \
      "$(csv_value "$csv" triangles_drawn)"
  done
  }
  section 3 && {
  echo
  echo "3. Pictures: $issue_count soldiers inside the crowd at $issue_size, against --raster hardware"
  for variant in "${variants[@]:1}"; do
    name=${variant%%:*}
    echo "$name: $("$bin/image-psnr" "$res/pictures/stress-$issue_count-t20-hardware.png" \
      "$res/pictures/stress-$issue_count-t20-$name.png" 2>&1)"
  done
  }
} | tee "$res/summary.txt"
tar -czf "$out/mesh-raster.tgz" -C /tmp mesh-raster
[[ $failures == 0 ]] || { echo "run_mesh_raster: $failures run(s) failed (see their .txt in mesh-raster.tgz)"; exit 1; }
