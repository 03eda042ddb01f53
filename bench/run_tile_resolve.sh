#!/usr/bin/env bash
# What the mesh path costs now that the visibility buffers' resolve covers only the tiles the compute
# rasterizers drew into (docs/compute-raster.md, "The resolve over covered tiles"), on a lent GPU machine,
# to set auto's gate (render::kAutoMeshRasterMinTriangles) from: crowd-bench, method compute, at SIZE,
# on paper-fig4 (10,240 soldiers flown over), the default scene, stress STRESS_COUNT from 20 s (inside the
# crowd) and stress IMPOSTOR_COUNT from above (t = 0) with impostors, each with --mesh-raster-limit 0 (no
# mesh in compute: the impostors' raster and resolve only), 64 (the small meshes in compute on every
# frame) and auto (the default: 64 once a frame drew the gate's triangles). Twice, interleaved so drift
# shows. Prints per run the frame's median and p95, the raster and draw (colour) passes, and the frame
# against limit 0; writes $OUT/tile-resolve.tgz (every run's output and CSV).
#
# Expects the Vulkan loader packages in .gl/ and crowd-bench in .devbin/ (carried; BIN names another
# folder: the same script over the binaries of the commit before the tiles gives the full-screen
# resolve's figures to compare with).
#   on the H100:      bash bench/run_tile_resolve.sh
#   here on lavapipe: DEVICE= BIN=build FRAMES=3 WARMUP=1 SIZE=480x270 PAPER_COUNT=4000 STRESS_COUNT=3000 \
#                     IMPOSTOR_COUNT=8000 bash bench/run_tile_resolve.sh
# FRAMES (default 200) and WARMUP (20) as crowd-bench's --frames and --warmup; DEVICE (NVIDIA): part of
# the device's name, empty for the first device; SIZE (1920x1080); PAPER_COUNT (paper-fig4's own, 10,240;
# lavapipe's 128 MiB storage-buffer range holds 9,510 with compute); STRESS_COUNT (100000); IMPOSTOR_COUNT
# (1000000); LIMITS ("0 64 auto").
set -uo pipefail
source "$(dirname "${BASH_SOURCE[0]}")/lent_machine.sh"
frames=${FRAMES:-200}
warmup=${WARMUP:-20}
device=${DEVICE-NVIDIA}
size=${SIZE:-1920x1080}
paper_count=${PAPER_COUNT:-}
stress_count=${STRESS_COUNT:-100000}
impostor_count=${IMPOSTOR_COUNT:-1000000}
read -r -a limits <<<"${LIMITS:-0 64 auto}"
bin=$(realpath "${BIN:-.devbin}")
res=/tmp/tile-resolve
out=${OUT:-/tmp/out}
probe() { "$bin/crowd-bench" "${device_flag[@]}" --counts 1 --frames 1 --warmup 0 --size 64x64 >"$res/probe.txt" 2>&1; }
begin_run run_tile_resolve

failures=0
scenes=(paper-fig4 default stress impostors)

# Percent by which $2 is over $1.
percent() { awk -v a="$1" -v b="$2" 'BEGIN { if (a + 0 > 0 && b != "") printf "%+.1f%%", 100 * (b - a) / a; else print "-" }'; }

scene_flags() {
  case $1 in
    paper-fig4) echo "--scene paper-fig4${paper_count:+ --counts $paper_count}" ;;
    default) echo "--scene default" ;;
    stress) echo "--scene stress --counts $stress_count --start 20" ;;
    impostors) echo "--scene stress --counts $impostor_count --start 0 --impostors on" ;;
  esac
}

for round in 1 2; do
  for scene in "${scenes[@]}"; do
    for limit in "${limits[@]}"; do
      key=$scene-$limit-$round
      # shellcheck disable=SC2046  # the flag function gives words
      run "bench-$key" "$bin/crowd-bench" "${device_flag[@]}" $(scene_flags "$scene") --raster auto \
        --mesh-raster-limit "$limit" --methods compute --frames "$frames" --warmup "$warmup" --size "$size" \
        --csv "$res/bench-$key.csv"
    done
  done
done

{
  echo
  echo "compute skinning, --raster auto, $size; crowd-bench over $frames frames after $warmup warm-up, in ms;"
  echo "frame: wall clock between frame starts (two frames in flight), median and p95; raster: the compute"
  echo "rasterizers' pass (clears, splits, rasterizing, tile scans); draw: the colour pass (with the resolves)"
  echo "($(csv_value "$res/bench-paper-fig4-${limits[0]}-1.csv" pass_clock)); vs ${limits[0]}: the median frame against"
  echo "--mesh-raster-limit ${limits[0]}. paper-fig4: ${paper_count:-10,240} flown over; default: the default scene; stress: $stress_count"
  echo "from 20 s, inside; impostors: stress $impostor_count from above, --impostors on. tris: mesh triangles drawn."
  printf "%-10s %-5s %1s | %8s %8s %8s | %8s %8s | %12s\n" scene limit r frame p95 "vs ${limits[0]}" raster draw tris
  for round in 1 2; do
    for scene in "${scenes[@]}"; do
      base=$res/bench-$scene-${limits[0]}-$round.csv
      for limit in "${limits[@]}"; do
        csv=$res/bench-$scene-$limit-$round.csv
        if [[ $(csv_value "$csv" status) != ok ]]; then
          printf "%-10s %-5s %1s | %8s\n" "$scene" "$limit" "$round" skipped
          continue
        fi
        printf "%-10s %-5s %1s | %8.3f %8.3f %8s | %8.3f %8.3f | %12s\n" "$scene" "$limit" "$round" \
          "$(csv_value "$csv" median_frame_ms)" "$(csv_value "$csv" p95_frame_ms)" \
          "$(percent "$(csv_value "$base" median_frame_ms)" "$(csv_value "$csv" median_frame_ms)")" \
          "$(csv_value "$csv" gpu_raster_ms)" "$(csv_value "$csv" gpu_draw_ms)" "$(csv_value "$csv" triangles_drawn)"
      done
    done
  done
} | tee "$res/summary.txt"
tar -czf "$out/tile-resolve.tgz" -C /tmp tile-resolve
[[ $failures == 0 ]] || { echo "run_tile_resolve: $failures run(s) failed (see their .txt in tile-resolve.tgz)"; exit 1; }
