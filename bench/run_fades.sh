#!/usr/bin/env bash
# What fades (--lod-fade) and the impostor blend (--impostor-blend) cost, on a lent GPU machine:
# crowd-bench, method compute, at 1920x1080 on paper-fig4 (10,240 soldiers flown over), stress 100,000
# from 20 s (inside the crowd) and stress 1,000,000 from above (t = 0) with impostors, each with
# --lod-fade on and off; the 1,000,000 impostors also with --impostor-blend off (fades on). Twice,
# interleaved so drift shows. Prints the medians (frame, GPU total, colour pass) against --lod-fade off,
# and writes $OUT/fades.tgz (every run's output and CSV).
#
# Expects the Vulkan loader packages in .gl/ and crowd-bench in .devbin/ (carried).
#   on the H100:      bash bench/run_fades.sh
#   here on lavapipe: DEVICE= FRAMES=3 WARMUP=1 SIZE=480x270 STRESS_COUNT=8000 IMPOSTOR_COUNT=20000 bash bench/run_fades.sh
# FRAMES (default 300) and WARMUP (30) as crowd-bench's --frames and --warmup; DEVICE (NVIDIA): part of
# the device's name, empty for the first device; SIZE (1920x1080); STRESS_COUNT (100000; lavapipe's
# 128 MiB storage-buffer range takes 8000 with compute); IMPOSTOR_COUNT (1000000).
set -uo pipefail
source "$(dirname "${BASH_SOURCE[0]}")/lent_machine.sh"
frames=${FRAMES:-300}
warmup=${WARMUP:-30}
device=${DEVICE-NVIDIA}
size=${SIZE:-1920x1080}
stress_count=${STRESS_COUNT:-100000}
impostor_count=${IMPOSTOR_COUNT:-1000000}
bin=$PWD/.devbin
res=/tmp/fades
out=${OUT:-/tmp/out}
probe() { "$bin/crowd-bench" "${device_flag[@]}" --counts 1 --frames 1 --warmup 0 --size 64x64 >"$res/probe.txt" 2>&1; }
begin_run run_fades

failures=0

# Percent by which $2 is over $1.
percent() { awk -v a="$1" -v b="$2" 'BEGIN { if (a + 0 > 0 && b != "") printf "%+.1f%%", 100 * (b - a) / a; else print "-" }'; }

scene_flags() {
  case $1 in
    paper-fig4) echo "--scene paper-fig4" ;;
    stress) echo "--scene stress --counts $stress_count --start 20" ;;
    impostors) echo "--scene stress --counts $impostor_count --start 0 --impostors on" ;;
  esac
}
# fade-off is the reference; fade-on the default; nearest: fades on, impostors show their nearest cell.
setting_flags() {
  case $1 in
    fade-off) echo "--lod-fade off" ;;
    fade-on) echo "--lod-fade on" ;;
    nearest) echo "--lod-fade on --impostor-blend off" ;;
  esac
}
settings_of() { if [[ $1 == impostors ]]; then echo "fade-off fade-on nearest"; else echo "fade-off fade-on"; fi; }

for round in 1 2; do
  for scene in paper-fig4 stress impostors; do
    for setting in $(settings_of $scene); do
      key=$scene-$setting-$round
      # shellcheck disable=SC2046  # the flag functions give words
      run "bench-$key" "$bin/crowd-bench" "${device_flag[@]}" $(scene_flags $scene) $(setting_flags $setting) \
        --methods compute --frames "$frames" --warmup "$warmup" --size "$size" --csv "$res/bench-$key.csv"
    done
  done
done

{
  echo
  echo "compute, $size; crowd-bench medians over $frames frames after $warmup warm-up, in ms; frame: wall clock between"
  echo "frame starts (two frames in flight); gpu: every pass's GPU time; draw: the colour pass"
  echo "($(csv_value "$res/bench-paper-fig4-fade-off-1.csv" pass_clock)). fade-off: --lod-fade off (the reference);"
  echo "fade-on: the default; nearest: fades on, --impostor-blend off. paper-fig4: 10,240 flown over; stress:"
  echo "$stress_count from 20 s, inside; impostors: stress $impostor_count from above, --impostors on."
  printf "%-10s %-9s %1s | %8s %8s | %8s %8s | %8s %8s\n" scene setting r frame "vs off" gpu "vs off" draw "vs off"
  for round in 1 2; do
    for scene in paper-fig4 stress impostors; do
      base=$res/bench-$scene-fade-off-$round.csv
      for setting in $(settings_of $scene); do
        csv=$res/bench-$scene-$setting-$round.csv
        if [[ $(csv_value "$csv" status) != ok ]]; then
          printf "%-10s %-9s %1s | %8s\n" "$scene" "$setting" "$round" skipped
          continue
        fi
        printf "%-10s %-9s %1s | %8.3f %8s | %8.3f %8s | %8.3f %8s\n" "$scene" "$setting" "$round" \
          "$(csv_value "$csv" median_frame_ms)" "$(percent "$(csv_value "$base" median_frame_ms)" "$(csv_value "$csv" median_frame_ms)")" \
          "$(csv_value "$csv" gpu_total_ms)" "$(percent "$(csv_value "$base" gpu_total_ms)" "$(csv_value "$csv" gpu_total_ms)")" \
          "$(csv_value "$csv" gpu_draw_ms)" "$(percent "$(csv_value "$base" gpu_draw_ms)" "$(csv_value "$csv" gpu_draw_ms)")"
      done
    done
  done
} | tee "$res/summary.txt"
tar -czf "$out/fades.tgz" -C /tmp fades
[[ $failures == 0 ]] || { echo "run_fades: $failures run(s) failed (see their .txt in fades.tgz)"; exit 1; }
