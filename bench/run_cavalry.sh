#!/usr/bin/env bash
# The cavalry scene's frame rate on a lent GPU machine (issue 20's target: 10,000 riders at >= 300 fps):
# crowd-bench --scene cavalry (riders and foot soldiers 3:1 in a column on the march, orbiting camera),
# method compute, 1920x1080, at about 10,000 and 100,000 riders (13,334 and 133,334 characters: the
# scene draws each character's model at random by its weight), and the 100,000 again with impostors on.
# Twice, interleaved so drift shows. Prints the medians and writes $OUT/cavalry.tgz (every run's output and CSV).
#
# Expects the Vulkan loader packages in .gl/ and crowd-bench in .devbin/ (carried).
#   on the H100:      bash bench/run_cavalry.sh
#   here on lavapipe: DEVICE= FRAMES=3 WARMUP=1 SIZE=480x270 COUNTS=400,4000 BINS=build bash bench/run_cavalry.sh
# FRAMES (default 300) and WARMUP (30) as crowd-bench's --frames and --warmup; DEVICE (NVIDIA): part of
# the device's name, empty for the first device; SIZE (1920x1080); COUNTS (13334,133334: characters);
# BINS (.devbin): the folder holding crowd-bench and crowd-render.
set -uo pipefail
source "$(dirname "${BASH_SOURCE[0]}")/lent_machine.sh"
frames=${FRAMES:-300}
warmup=${WARMUP:-30}
device=${DEVICE-NVIDIA}
size=${SIZE:-1920x1080}
IFS=, read -r -a counts <<<"${COUNTS:-13334,133334}"
bin=$PWD/${BINS:-.devbin}
res=/tmp/cavalry
out=${OUT:-/tmp/out}
probe() { "$bin/crowd-bench" "${device_flag[@]}" --counts 1 --frames 1 --warmup 0 --size 64x64 >"$res/probe.txt" 2>&1; }
begin_run run_cavalry

failures=0
largest=${counts[${#counts[@]} - 1]}
# Each configuration: NAME COUNT EXTRA-FLAGS...
configurations() {
  for count in "${counts[@]}"; do echo "meshes-$count $count"; done
  echo "impostors-$largest $largest --impostors on"
}

for round in 1 2; do
  while read -r name count extra; do
    # shellcheck disable=SC2086  # extra holds flags
    run "bench-$name-$round" "$bin/crowd-bench" "${device_flag[@]}" --scene cavalry --counts "$count" $extra \
      --methods compute --frames "$frames" --warmup "$warmup" --size "$size" --csv "$res/bench-$name-$round.csv"
  done < <(configurations)
done

{
  echo
  echo "cavalry scene, compute, $size; crowd-bench medians over $frames frames after $warmup warm-up; frame:"
  echo "wall clock between frame starts (two frames in flight); gpu: every pass's GPU time"
  echo "($(csv_value "$res/bench-meshes-${counts[0]}-1.csv" pass_clock)); riders: about 3/4 of the characters."
  printf "%-18s %1s | %10s %8s | %9s %9s %9s %9s | %14s\n" configuration r characters fps "frame ms" "p95 ms" "gpu ms" "draw ms" "LOD 0/1/2"
  for round in 1 2; do
    while read -r name count extra; do
      csv=$res/bench-$name-$round.csv
      if [[ $(csv_value "$csv" status) != ok ]]; then
        printf "%-18s %1s | %10s\n" "$name" "$round" skipped
        continue
      fi
      printf "%-18s %1s | %10s %8.1f | %9.3f %9.3f %9.3f %9.3f | %14s\n" "$name" "$round" "$count" \
        "$(csv_value "$csv" fps)" "$(csv_value "$csv" median_frame_ms)" "$(csv_value "$csv" p95_frame_ms)" \
        "$(csv_value "$csv" gpu_total_ms)" "$(csv_value "$csv" gpu_draw_ms)" \
        "$(csv_value "$csv" visible_lod0)/$(csv_value "$csv" visible_lod1)/$(csv_value "$csv" visible_lod2)"
    done < <(configurations)
  done
} | tee "$res/summary.txt"
tar -czf "$out/cavalry.tgz" -C /tmp cavalry
[[ $failures == 0 ]] || { echo "run_cavalry: $failures run(s) failed (see their .txt in cavalry.tgz)"; exit 1; }
