#!/usr/bin/env bash
# What shadow cascades (--shadow-cascades) cost, on a lent GPU machine: crowd-bench, method compute, at
# 1920x1080 on paper-fig4 (10,240 soldiers flown over), the default scene and stress 100,000 from 20 s
# (inside the crowd), each with shadows off and with 1, 2 and 4 cascades. Twice, interleaved so drift
# shows. Prints the medians (frame, p95, shadow pass, colour pass) and the frame against shadows off,
# renders the default scene and the stress crowd with 1 and 4 cascades (crowd-render, PNGs, with their
# PSNR against each other), and writes $OUT/cascades.tgz (every run's output, CSV and picture).
#
# Expects the Vulkan loader packages in .gl/ and crowd-bench, crowd-render, image-psnr in .devbin/ (carried).
#   on the H100:      bash bench/run_cascades.sh
#   here on lavapipe: DEVICE= FRAMES=3 WARMUP=1 SIZE=480x270 STRESS_COUNT=4000 bash bench/run_cascades.sh
# FRAMES (default 200) and WARMUP (20) as crowd-bench's --frames and --warmup; DEVICE (NVIDIA): part of
# the device's name, empty for the first device; SIZE (1920x1080); STRESS_COUNT (100000).
set -uo pipefail
source "$(dirname "${BASH_SOURCE[0]}")/lent_machine.sh"
frames=${FRAMES:-200}
warmup=${WARMUP:-20}
device=${DEVICE-NVIDIA}
size=${SIZE:-1920x1080}
stress_count=${STRESS_COUNT:-100000}
bin=$PWD/.devbin
res=/tmp/cascades
out=${OUT:-/tmp/out}
probe() { "$bin/crowd-bench" "${device_flag[@]}" --counts 1 --frames 1 --warmup 0 --size 64x64 >"$res/probe.txt" 2>&1; }
begin_run run_cascades

failures=0

# Percent by which $2 is over $1.
percent() { awk -v a="$1" -v b="$2" 'BEGIN { if (a + 0 > 0 && b != "") printf "%+.1f%%", 100 * (b - a) / a; else print "-" }'; }

scenes="paper-fig4 default stress"
settings="off c1 c2 c4"
scene_flags() {
  case $1 in
    paper-fig4) echo "--scene paper-fig4" ;;
    default) echo "--scene default" ;;
    stress) echo "--scene stress --counts $stress_count --start 20" ;;
  esac
}
setting_flags() {
  case $1 in
    off) echo "--shadows off" ;;
    c*) echo "--shadows on --shadow-cascades ${1#c}" ;;
  esac
}

for round in 1 2; do
  for scene in $scenes; do
    for setting in $settings; do
      key=$scene-$setting-$round
      # shellcheck disable=SC2046  # the flag functions give words
      run "bench-$key" "$bin/crowd-bench" "${device_flag[@]}" $(scene_flags $scene) $(setting_flags $setting) \
        --methods compute --frames "$frames" --warmup "$warmup" --size "$size" --csv "$res/bench-$key.csv"
    done
  done
done

# Pictures: the still default scene and the crowd seen from inside, one cascade and four.
for scene in default stress; do
  [[ $scene == stress ]] && flags="--scene stress --count $stress_count --start 20" || flags="--scene default"
  for c in 1 4; do
    # shellcheck disable=SC2086  # the flags are words
    run "render-$scene-c$c" "$bin/crowd-render" "${device_flag[@]}" $flags --method compute --shadow-cascades $c \
      --size "$size" --frames 10 --out "$res/$scene-c$c.png"
  done
  run "psnr-$scene" "$bin/image-psnr" "$res/$scene-c1.png" "$res/$scene-c4.png"
done

{
  echo
  echo "compute, $size; crowd-bench over $frames frames after $warmup warm-up, in ms; frame: median wall clock between"
  echo "frame starts (two frames in flight), p95 of the same; shadow: the shadow pass's GPU time; draw: the colour pass"
  echo "($(csv_value "$res/bench-paper-fig4-off-1.csv" pass_clock)). off: --shadows off; cN: shadows with N cascades."
  echo "paper-fig4: 10,240 flown over; default: 1,024 still; stress: $stress_count from 20 s, inside."
  printf "%-10s %-4s %1s | %8s %8s %8s | %8s %8s\n" scene set r frame p95 "vs off" shadow draw
  for round in 1 2; do
    for scene in $scenes; do
      base=$res/bench-$scene-off-$round.csv
      for setting in $settings; do
        csv=$res/bench-$scene-$setting-$round.csv
        if [[ $(csv_value "$csv" status) != ok ]]; then
          printf "%-10s %-4s %1s | %8s\n" "$scene" "$setting" "$round" skipped
          continue
        fi
        printf "%-10s %-4s %1s | %8.3f %8.3f %8s | %8.3f %8.3f\n" "$scene" "$setting" "$round" \
          "$(csv_value "$csv" median_frame_ms)" "$(csv_value "$csv" p95_frame_ms)" \
          "$(percent "$(csv_value "$base" median_frame_ms)" "$(csv_value "$csv" median_frame_ms)")" \
          "$(csv_value "$csv" gpu_shadow_ms)" "$(csv_value "$csv" gpu_draw_ms)"
      done
    done
  done
  echo
  for scene in default stress; do echo "$scene, 4 cascades against 1: $(cat "$res/psnr-$scene.txt" 2>/dev/null | tail -1)"; done
} | tee "$res/summary.txt"
tar -czf "$out/cascades.tgz" -C /tmp cascades
[[ $failures == 0 ]] || { echo "run_cascades: $failures run(s) failed (see their .txt in cascades.tgz)"; exit 1; }
