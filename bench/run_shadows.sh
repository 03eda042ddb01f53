#!/usr/bin/env bash
# What shadows cost, on a lent GPU machine: crowd-bench on paper-fig4 (10,240 soldiers flown over) and
# stress (100,000 soldiers from 20 s, inside the crowd) at 1920x1080, methods compute and two-pass, with
# shadows off, on with shadow LOD (the default), on with its mesh casters rasterized in compute (--shadow-raster
# compute) and on without shadow LOD (--shadow-lod off: casters at their level
# in view), twice, interleaved so drift shows; crowd-render's picture of each (the same frame: the last of
# FRAMES). Prints the medians, the shadow pass's share and triangles, and writes $OUT/shadows.tgz (every
# run's output, the CSVs, the pictures).
#
# Expects the Vulkan loader packages in .gl/ and crowd-bench and crowd-render in .devbin/ (carried).
#   on the H100:      bash bench/run_shadows.sh
#   here on lavapipe: DEVICE= FRAMES=3 WARMUP=1 SIZE=480x270 STRESS_COUNT=8000 bash bench/run_shadows.sh
# FRAMES (default 300) and WARMUP (30) as crowd-bench's --frames and --warmup; DEVICE (NVIDIA): part of
# the device's name, empty for the first device; SIZE (1920x1080); STRESS_COUNT (100000; lavapipe's
# 128 MiB storage-buffer range takes 8000 with compute).
set -uo pipefail
source "$(dirname "${BASH_SOURCE[0]}")/lent_machine.sh"
frames=${FRAMES:-300}
warmup=${WARMUP:-30}
device=${DEVICE-NVIDIA}
size=${SIZE:-1920x1080}
stress_count=${STRESS_COUNT:-100000}
bin=$PWD/.devbin
res=/tmp/shadows
out=${OUT:-/tmp/out}
begin_run run_shadows
mkdir -p "$res/pictures"

failures=0

# Percent by which $2 is over $1.
percent() { awk -v a="$1" -v b="$2" 'BEGIN { if (a + 0 > 0 && b != "") printf "%+.0f%%", 100 * (b - a) / a; else print "-" }'; }

scene_flags() {  # bench|render scene
  case $2 in
    paper-fig4) ;;
    stress) local count=--count
            [[ $1 == bench ]] && count=--counts  # crowd-bench measures lists
            echo "$count $stress_count --start 20" ;;
  esac
}
# The three shadow settings: off, on (shadow LOD, the default), on without shadow LOD.
shadow_flags() {
  case $1 in
    off) echo "--shadows off" ;;
    lod) echo "--shadows on --shadow-lod on" ;;
    compute) echo "--shadows on --shadow-lod on --shadow-raster compute" ;;
    view-lod) echo "--shadows on --shadow-lod off" ;;
  esac
}

for round in 1 2; do
  for scene in paper-fig4 stress; do
    for method in compute two-pass; do
      for shadows in off lod compute view-lod; do
        key=$scene-$method-$shadows-$round
        # shellcheck disable=SC2046  # the flag functions give words
        run "bench-$key" "$bin/crowd-bench" "${device_flag[@]}" --scene $scene $(scene_flags bench $scene) \
          $(shadow_flags $shadows) --methods $method --frames "$frames" --warmup "$warmup" --size "$size" \
          --csv "$res/bench-$key.csv"
        if [[ $round == 1 ]]; then
          # shellcheck disable=SC2046
          run "render-$scene-$method-$shadows" "$bin/crowd-render" "${device_flag[@]}" --scene $scene \
            $(scene_flags render $scene) $(shadow_flags $shadows) --method $method --frames "$frames" --size "$size" \
            --out "$res/pictures/$scene-$method-$shadows.png"
        fi
      done
    done
  done
done

{
  echo
  echo "Medians over $frames frames after $warmup warm-up at $size, in ms; frame: wall clock between frame starts"
  echo "(two frames in flight); shadow, draw: the passes' GPU time ($(csv_value "$res/bench-paper-fig4-compute-off-1.csv" pass_clock))."
  echo "lod: shadows on with shadow LOD (the default); compute: the same with --shadow-raster compute (mesh casters"
  echo "rasterized in compute); view-lod: --shadow-lod off (casters at their level in view)."
  echo "vs off: the frame over shadows off's. shadow tris: triangles drawn into the shadow map, M; skinned tris: the"
  echo "characters skinned this frame (in view, and casters out of view at their shadow level), M."
  echo "Mtri/s: shadow tris over the shadow pass's time (impostor casters and the map's clear included)."
  printf "%-10s %-8s %-8s %1s | %8s %7s | %8s %8s | %11s %10s %8s\n" scene method shadows r frame "vs off" shadow draw \
    "shadow tris" "skinned tris" "Mtri/s"
  for round in 1 2; do
    for scene in paper-fig4 stress; do
      for method in compute two-pass; do
        off_frame=$(csv_value "$res/bench-$scene-$method-off-$round.csv" median_frame_ms)
        for shadows in off lod compute view-lod; do
          csv=$res/bench-$scene-$method-$shadows-$round.csv
          if [[ $(csv_value "$csv" status) != ok ]]; then
            printf "%-10s %-8s %-8s %1s | %8s\n" "$scene" "$method" "$shadows" "$round" skipped
            continue
          fi
          frame=$(csv_value "$csv" median_frame_ms)
          printf "%-10s %-8s %-8s %1s | %8.3f %7s | %8.3f %8.3f | %11.2f %10.2f %8.0f\n" "$scene" "$method" "$shadows" "$round" \
            "$frame" "$(percent "$off_frame" "$frame")" "$(csv_value "$csv" gpu_shadow_ms)" \
            "$(csv_value "$csv" gpu_draw_ms)" "$(awk -v t="$(csv_value "$csv" shadow_triangles)" 'BEGIN { print t / 1e6 }')" \
            "$(awk -v t="$(csv_value "$csv" triangles_drawn)" 'BEGIN { print t / 1e6 }')" \
            "$(awk -v t="$(csv_value "$csv" shadow_triangles)" -v ms="$(csv_value "$csv" gpu_shadow_ms)" \
               'BEGIN { print (ms > 0 ? t / ms / 1e3 : 0) }')"
        done
      done
    done
  done
  echo
  echo "The compute raster's picture against the hardware one's (the same frame, shadow LOD on):"
  for scene in paper-fig4 stress; do
    for method in compute two-pass; do
      printf "%-10s %-8s " "$scene" "$method"
      "$bin/image-psnr" "$res/pictures/$scene-$method-lod.png" "$res/pictures/$scene-$method-compute.png" 2>&1 | tail -1
    done
  done
} | tee "$res/summary.txt"
tar -czf "$out/shadows.tgz" -C /tmp shadows
[[ $failures == 0 ]] || { echo "run_shadows: $failures run(s) failed (see their .txt in shadows.tgz)"; exit 1; }
