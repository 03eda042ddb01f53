#!/usr/bin/env bash
# What props cost (issue 20, docs/props.md), on a lent GPU machine: crowd-bench at 1920x1080 on
# paper-fig4 (10,240 soldiers flown over, every one with a rifle, one in eight also a flag) with --props
# on and off, for the methods compute and two-pass (the paper's); three rounds, interleaved so drift
# shows. The issue's target: props cost at most 20 % of the frame. Prints the medians (frame, GPU total,
# skinning and colour passes) against --props off, and writes $OUT/props.tgz (every run's output and CSV).
#
# Expects the Vulkan loader packages in .gl/ and crowd-bench in .devbin/ (carried).
#   on the H100:      bash bench/run_props.sh
#   here on lavapipe: DEVICE= FRAMES=5 WARMUP=1 SIZE=480x270 bash bench/run_props.sh
#     (compute with props is skipped there: 10,240 soldiers' skinned positions, 137.8 MiB, pass lavapipe's
#     128 MiB storage-buffer range; METHODS=two-pass runs only what it can)
# FRAMES (default 300) and WARMUP (30) as crowd-bench's --frames and --warmup; DEVICE (NVIDIA): part of
# the device's name, empty for the first device; SIZE (1920x1080); METHODS (compute two-pass).
set -uo pipefail
source "$(dirname "${BASH_SOURCE[0]}")/lent_machine.sh"
frames=${FRAMES:-300}
warmup=${WARMUP:-30}
device=${DEVICE-NVIDIA}
size=${SIZE:-1920x1080}
methods=${METHODS:-compute two-pass}
bin=$PWD/.devbin
res=/tmp/props
out=${OUT:-/tmp/out}
probe() { "$bin/crowd-bench" "${device_flag[@]}" --counts 1 --frames 1 --warmup 0 --size 64x64 >"$res/probe.txt" 2>&1; }
begin_run run_props

failures=0

# Percent by which $2 is over $1.
percent() { awk -v a="$1" -v b="$2" 'BEGIN { if (a + 0 > 0 && b != "") printf "%+.1f%%", 100 * (b - a) / a; else print "-" }'; }

for round in 1 2 3; do
  for method in $methods; do
    for props in off on; do
      key=$method-$props-$round
      run "bench-$key" "$bin/crowd-bench" "${device_flag[@]}" --scene paper-fig4 --props "$props" \
        --methods "$method" --frames "$frames" --warmup "$warmup" --size "$size" --csv "$res/bench-$key.csv"
    done
  done
done

{
  echo
  echo "paper-fig4, $size; crowd-bench medians over $frames frames after $warmup warm-up, in ms; frame: wall clock"
  echo "between frame starts (two frames in flight); gpu: every pass's GPU time; skin: the skinning pass; draw:"
  echo "the colour pass ($(csv_value "$res/bench-${methods%% *}-off-1.csv" pass_clock)). off: --props off (the soldier"
  echo "without props, 1,020 triangles); on: the default (a rifle each, one in eight a flag; 1,116 triangles)."
  printf "%-9s %-5s %1s | %8s %8s | %8s %8s | %8s %8s | %8s %8s\n" method props r frame "vs off" gpu "vs off" skin "vs off" draw "vs off"
  for round in 1 2 3; do
    for method in $methods; do
      base=$res/bench-$method-off-$round.csv
      for props in off on; do
        csv=$res/bench-$method-$props-$round.csv
        if [[ $(csv_value "$csv" status) != ok ]]; then
          printf "%-9s %-5s %1s | %8s\n" "$method" "$props" "$round" skipped
          continue
        fi
        printf "%-9s %-5s %1s | %8.3f %8s | %8.3f %8s | %8.3f %8s | %8.3f %8s\n" "$method" "$props" "$round" \
          "$(csv_value "$csv" median_frame_ms)" "$(percent "$(csv_value "$base" median_frame_ms)" "$(csv_value "$csv" median_frame_ms)")" \
          "$(csv_value "$csv" gpu_total_ms)" "$(percent "$(csv_value "$base" gpu_total_ms)" "$(csv_value "$csv" gpu_total_ms)")" \
          "$(csv_value "$csv" gpu_skin_ms)" "$(percent "$(csv_value "$base" gpu_skin_ms)" "$(csv_value "$csv" gpu_skin_ms)")" \
          "$(csv_value "$csv" gpu_draw_ms)" "$(percent "$(csv_value "$base" gpu_draw_ms)" "$(csv_value "$csv" gpu_draw_ms)")"
      done
    done
  done
} | tee "$res/summary.txt"
tar -czf "$out/props.tgz" -C /tmp props
[[ $failures == 0 ]] || { echo "run_props: $failures run(s) failed (see their .txt in props.tgz)"; exit 1; }
