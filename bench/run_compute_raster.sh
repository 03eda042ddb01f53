#!/usr/bin/env bash
# The compute rasterizer of impostors (docs/compute-raster.md) against the hardware rasterizer, on a
# lent GPU machine:
#  1. rates and the crossover: the stress scene from high above (t = 0 s) at SIZE with every character an
#     impostor whatever its size (--lod-thresholds 100000,50000 --impostor-threshold 40000), shadows off,
#     for crowds from SWEEP_COUNTS: the fewer the characters, the larger each on screen (the crowd fills
#     the view), so the sweep runs from a few pixels to a few hundred per impostor. Per row, each path's
#     GPU time for the impostors (hardware: the draw pass; compute: the raster pass plus the draw pass,
#     which holds the resolve) and impostors per second. Both draw passes include the ground.
#  2. the issue's frames: ISSUE_COUNTS soldiers from above and inside the crowd (t = 20 s) at ISSUE_SIZE,
#     impostors at their defaults, shadows on, --raster hardware, compute and auto: frame time, fps, passes.
#  3. pictures: crowd-render's last frame of the first ISSUE_COUNTS crowd, from above and inside, with each
#     rasterizer, and image-psnr of compute and auto against hardware.
# Prints the tables and writes $OUT/compute-raster.tgz (every run's output, the CSVs, the pictures).
#
# Expects the Vulkan loader packages in .gl/ and crowd-bench, crowd-render and image-psnr in .devbin/
# (carried; BIN names another folder).
#   on the H100:      bash bench/run_compute_raster.sh
#   here on lavapipe: DEVICE= BIN=build FRAMES=3 WARMUP=1 SIZE=480x270 ISSUE_SIZE=480x270 \
#                     SWEEP_COUNTS="3000 300 30" ISSUE_COUNTS=3000 bash bench/run_compute_raster.sh
# FRAMES (default 60) and WARMUP (10) as crowd-bench's --frames and --warmup; DEVICE (NVIDIA): part of the
# device's name, empty for the first device; SIZE (3840x2160); SWEEP_COUNTS (1000000 250000 62500 15625
# 3906 977 244); ISSUE_SIZE (1920x1080); ISSUE_COUNTS (1000000 4000000 10000000); SECTIONS ("1 2 3"): which
# of the three to run.
set -uo pipefail
source "$(dirname "${BASH_SOURCE[0]}")/lent_machine.sh"
frames=${FRAMES:-60}
warmup=${WARMUP:-10}
device=${DEVICE-NVIDIA}
size=${SIZE:-3840x2160}
issue_size=${ISSUE_SIZE:-1920x1080}
read -r -a sweep_counts <<<"${SWEEP_COUNTS:-1000000 250000 62500 15625 3906 977 244}"
read -r -a issue_counts <<<"${ISSUE_COUNTS:-1000000 4000000 10000000}"
bin=$(realpath "${BIN:-.devbin}")
res=/tmp/compute-raster
out=${OUT:-/tmp/out}
begin_run run_compute_raster
mkdir -p "$res/pictures"

failures=0
every_impostor=(--impostors on --lod-thresholds 100000,50000 --impostor-threshold 40000)
rasters=(hardware compute auto)
sections=" ${SECTIONS:-1 2 3} "
section() { [[ $sections == *" $1 "* ]]; }

# 1. The sweep (hardware and compute; auto would send the large ones to the hardware), after the ground
# alone (one impostor: the scene's ground fills the view from above whatever the crowd).
section 1 && run "sweep-ground" "$bin/crowd-bench" "${device_flag[@]}" --scene stress --counts 1 --methods compute \
  "${every_impostor[@]}" --shadows off --raster hardware --frames "$frames" --warmup "$warmup" --size "$size" \
  --csv "$res/sweep-ground.csv"
section 1 && for count in "${sweep_counts[@]}"; do
  for raster in hardware compute; do
    run "sweep-$count-$raster" "$bin/crowd-bench" "${device_flag[@]}" --scene stress --counts "$count" --methods compute \
      "${every_impostor[@]}" --shadows off --raster $raster --frames "$frames" --warmup "$warmup" --size "$size" \
      --csv "$res/sweep-$count-$raster.csv"
  done
done

# 2. The issue's frames.
section 2 && for count in "${issue_counts[@]}"; do
  for start in 0 20; do
    for raster in "${rasters[@]}"; do
      run "issue-$count-t$start-$raster" "$bin/crowd-bench" "${device_flag[@]}" --scene stress --counts "$count" \
        --start $start --methods compute --impostors on --raster $raster --frames "$frames" --warmup "$warmup" \
        --size "$issue_size" --csv "$res/issue-$count-t$start-$raster.csv"
    done
  done
done

# 3. Pictures of the first crowd.
section 3 && for start in 0 20; do
  for raster in "${rasters[@]}"; do
    run "picture-t$start-$raster" "$bin/crowd-render" "${device_flag[@]}" --scene stress --count "${issue_counts[0]}" \
      --start $start --method compute --impostors on --raster $raster --frames 3 --size "$issue_size" \
      --out "$res/pictures/stress-${issue_counts[0]}-t$start-$raster.png"
  done
done

ok() { [[ $(csv_value "$1" status) == ok ]]; }

{
  section 1 && {
  echo
  echo "1. Impostors per second, stress from above at $size, every character an impostor, shadows off; medians over"
  echo "$frames frames after $warmup warm-up ($(csv_value "$res/sweep-${sweep_counts[0]}-hardware.csv" pass_clock))."
  ground=$(csv_value "$res/sweep-ground.csv" gpu_draw_ms)
  echo "px/imp: screen pixels per impostor (the crowd fills the view). hardware: the draw pass; compute: raster +"
  echo "draw (the resolve). Both draws hold the ground, ${ground:-?} ms alone (one impostor), taken off for ns/imp"
  echo "(GPU ns per impostor) and M imp/s (millions of impostors per second); cs/hw: compute's ns/imp over hardware's."
  printf "%10s %10s %8s | %9s %10s %9s | %9s %9s %10s %9s | %7s\n" characters impostors px/imp "hw draw" "ns/imp" \
    "M imp/s" raster "cs draw" "ns/imp" "M imp/s" "cs/hw"
  for count in "${sweep_counts[@]}"; do
    hw=$res/sweep-$count-hardware.csv cs=$res/sweep-$count-compute.csv
    if ! ok "$hw" || ! ok "$cs"; then printf "%10s %10s\n" "$count" skipped; continue; fi
    awk -v n="$count" -v imp="$(csv_value "$cs" impostors)" -v w="$(csv_value "$cs" width)" -v h="$(csv_value "$cs" height)" \
      -v hd="$(csv_value "$hw" gpu_draw_ms)" -v cr="$(csv_value "$cs" gpu_raster_ms)" -v cd="$(csv_value "$cs" gpu_draw_ms)" \
      -v g="${ground:-0}" '
      function rate(ms) { return ms > 0 ? i / (ms * 1e3) : 0 }
      BEGIN {
        i = imp > 0 ? imp : 1; hw = hd - g; cs = cr + cd - g
        printf "%10d %10d %8.1f | %9.3f %10.2f %9.3f | %9.3f %9.3f %10.2f %9.3f | %7.2f\n", n, imp, w * h / i, hd,
          hw * 1e6 / i, rate(hw), cr, cd, cs * 1e6 / i, rate(cs), (hw > 0 ? cs / hw : 0)
      }'
  done
  }
  section 2 && {
  echo
  echo "2. The issue's frames: stress at $issue_size, impostors at their defaults, shadows on; frame: wall clock between"
  echo "frame starts (two in flight); GPU ms per pass."
  printf "%10s %5s %-8s | %9s %7s | %8s %8s %8s | %10s\n" characters t raster frame fps shadow raster draw impostors
  for count in "${issue_counts[@]}"; do
    for start in 0 20; do
      for raster in "${rasters[@]}"; do
        csv=$res/issue-$count-t$start-$raster.csv
        if ! ok "$csv"; then printf "%10s %5s %-8s | skipped (%s)\n" "$count" "$start" "$raster" \
          "$(tail -1 "$res/issue-$count-t$start-$raster.txt" | cut -c1-80)"; continue; fi
        printf "%10s %5s %-8s | %9.3f %7.1f | %8.3f %8.3f %8.3f | %10.0f\n" "$count" "$start" "$raster" \
          "$(csv_value "$csv" median_frame_ms)" "$(csv_value "$csv" fps)" "$(csv_value "$csv" gpu_shadow_ms)" \
          "$(csv_value "$csv" gpu_raster_ms)" "$(csv_value "$csv" gpu_draw_ms)" "$(csv_value "$csv" impostors)"
      done
    done
  done
  }
  section 3 && {
  echo
  echo "3. Pictures: ${issue_counts[0]} soldiers at $issue_size, against --raster hardware"
  for start in 0 20; do
    for raster in compute auto; do
      echo "t = $start s, $raster: $("$bin/image-psnr" "$res/pictures/stress-${issue_counts[0]}-t$start-hardware.png" \
        "$res/pictures/stress-${issue_counts[0]}-t$start-$raster.png" 2>&1)"
    done
  done
  }
} | tee "$res/summary.txt"
tar -czf "$out/compute-raster.tgz" -C /tmp compute-raster
[[ $failures == 0 ]] || { echo "run_compute_raster: $failures run(s) failed (see their .txt in compute-raster.tgz)"; exit 1; }
