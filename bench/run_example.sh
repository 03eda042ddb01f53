#!/usr/bin/env bash
# The library inside a host against the programs, on a lent GPU machine: the same frames of paper-fig4
# (10,240 soldiers flown over) and stress (100,000 soldiers from 20 s) at 1920x1080, with the compute
# and two-pass methods, drawn by crowd-bench and by examples/embed_headless — once with --crowd-only
# (what crowd-bench draws: the library's ground and the crowd) and once with the host's own ground,
# boxes and ID pass — interleaved, twice, so drift shows. Prints the medians side by side and writes
# $OUT/example.tgz (every run's output, the CSVs, the last frames' images).
#
# Expects the Vulkan loader packages in .gl/ and crowd-bench, embed_headless and their shared
# libraries in .devbin/ (carried).
#   on the H100:      bash bench/run_example.sh
#   here on lavapipe: DEVICE= FRAMES=3 WARMUP=1 SIZE=480x270 STRESS_COUNT=8000 bash bench/run_example.sh
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
res=/tmp/example
out=${OUT:-/tmp/out}
# The example finds the device by name, or the NVIDIA driver is not among the loader's: name its ICD.
probe() { "$bin/embed_headless" "${device_flag[@]}" --count 1 "$res" 64x64 1 >"$res/probe.txt" 2>&1; }
begin_run run_example

failures=0

# The value of key $2 on the example's "timing" line in $1.
timing_value() { sed -n "s/^timing .* $2=\([^ ]*\).*/\1/p" "$1" 2>/dev/null | head -1; }
# Percent by which $2 is over $1.
percent() { awk -v a="$1" -v b="$2" 'BEGIN { if (a + 0 > 0 && b != "") printf "%+.1f%%", 100 * (b - a) / a; else print "-" }'; }

scene_flags() {  # bench|example scene
  case $2 in
    paper-fig4) ;;
    stress) local count=--count
            [[ $1 == bench ]] && count=--counts  # crowd-bench measures lists
            echo "$count $stress_count --start 20" ;;
  esac
}

for round in 1 2; do
  for scene in paper-fig4 stress; do
    for method in compute two-pass; do
      key=$scene-$method-$round
      # shellcheck disable=SC2046  # scene_flags gives words
      run "bench-$key" "$bin/crowd-bench" "${device_flag[@]}" --scene $scene $(scene_flags bench $scene) \
        --methods $method --frames "$frames" --warmup "$warmup" --size "$size" --csv "$res/bench-$key.csv"
      for host in crowd-only host; do
        mkdir -p "$res/$host-$key"
        crowd_only=(); [[ $host == crowd-only ]] && crowd_only=(--crowd-only)
        # shellcheck disable=SC2046
        run "$host-$key" "$bin/embed_headless" "${device_flag[@]}" --scene $scene $(scene_flags example $scene) \
          --method $method --warmup "$warmup" "${crowd_only[@]}" "$res/$host-$key" "$size" "$frames"
      done
    done
  done
done

{
  echo
  echo "Medians over $frames frames after $warmup warm-up at $size, in ms."
  echo "gpu: from the frame's first command to the end of the crowd's colour pass (crowd-bench: its GPU total, by"
  echo "     $(csv_value "$res/bench-paper-fig4-compute-1.csv" pass_clock); the example: timestamps in its own command buffer)."
  echo "frm: wall clock between frame starts, two frames in flight."
  echo "only: the example with --crowd-only, drawing what crowd-bench draws. host: with its own ground and boxes in"
  echo "     the colour pass (crwd) and its ID pass after it (all). LOD: characters drawn per level of detail."
  printf "%-10s %-8s %1s | %9s %9s %7s | %9s %9s %7s | %9s %9s %9s | %-17s %s\n" scene method r \
    "bench gpu" "only gpu" "diff" "bench frm" "only frm" "diff" "host crwd" "host all" "host frm" "LOD bench" "LOD example"
  for round in 1 2; do
    for scene in paper-fig4 stress; do
      for method in compute two-pass; do
        key=$scene-$method-$round
        csv=$res/bench-$key.csv only_txt=$res/crowd-only-$key.txt host_txt=$res/host-$key.txt
        bench_gpu='' bench_frame='' bench_lod=-
        if [[ $(csv_value "$csv" status) == ok ]]; then  # a skipped row has zeros
          bench_gpu=$(csv_value "$csv" gpu_total_ms) bench_frame=$(csv_value "$csv" median_frame_ms)
          bench_lod="$(csv_value "$csv" visible_lod0)/$(csv_value "$csv" visible_lod1)/$(csv_value "$csv" visible_lod2)"
        fi
        only_gpu=$(timing_value "$only_txt" crowd_gpu_median_ms) only_frame=$(timing_value "$only_txt" frame_median_ms)
        only_lod=$(timing_value "$only_txt" lod_median)
        host_crowd=$(timing_value "$host_txt" crowd_gpu_median_ms) host_all=$(timing_value "$host_txt" gpu_median_ms)
        host_frame=$(timing_value "$host_txt" frame_median_ms)
        printf "%-10s %-8s %1s | %9s %9s %7s | %9s %9s %7s | %9s %9s %9s | %-17s %s\n" \
          "$scene" "$method" "$round" "${bench_gpu:--}" "${only_gpu:--}" "$(percent "$bench_gpu" "$only_gpu")" \
          "${bench_frame:--}" "${only_frame:--}" "$(percent "$bench_frame" "$only_frame")" \
          "${host_crowd:--}" "${host_all:--}" "${host_frame:--}" "$bench_lod" "${only_lod:--}"
      done
    done
  done
} | tee "$res/summary.txt"
tar -czf "$out/example.tgz" -C /tmp example
[[ $failures == 0 ]] || { echo "run_example: $failures run(s) failed (see their .txt in example.tgz)"; exit 1; }
