#!/usr/bin/env bash
# Two builds against each other on a lent GPU machine: BEFORE (.devbin/before) and AFTER (.devbin/after),
# interleaved, compute skinning unless named, 1920x1080, shadows on (the default). First written for fades
# between mesh levels as geomorphs against the dithered double draws (as run_lod_morph_ab.sh), then used
# for each change of the colour pass since:
# 1. Cost (PARTS has "cost"): crowd-bench, 200 frames after 20, both builds interleaved in ROUNDS
#    rounds: paper-fig4 with compute and two-pass, with fades on (the default) and off; stress
#    100,000 from 20 s (inside the crowd); the default scene. Median and p95 frame, shadow and colour
#    pass, GPU total, and the characters drawn at each level.
#    With CONFIGS=wide instead: cavalry (about 10,000 riders), stress 250,000 inside with every one a
#    mesh, stress 1,000,000 inside with impostors, paper-fig4 with a 5 % band (--lod-hysteresis 0.05)
#    and paper-fig4 with vs-instanced.
#    With CONFIGS=shadows: stress 100,000 inside with shadows on and off (issue 18's shadow cost; paper-fig4's
#    is in the first list).
#    With CONFIGS=mill: 1,000,000 milling soldiers with impostors inside the crowd (from 20 s) and from
#    above (from 30 s), for issue 18's p95 (run with FRAMES=600 WARMUP=60, as bench/run_planning.sh).
# 2. Pictures (PARTS has "pictures"): paper-fig4's 60th frame from each build with fades on and off,
#    compared by image-psnr; the PNGs land in $OUT.
# Writes $OUT/two-builds.tgz (every run's output, CSV, commands and summary).
#
# Expects the Vulkan loader packages in .gl/, BEFORE's binaries (crowd-bench, crowd-render, image-psnr
# with their shared libraries) in BEFORE (.devbin/before) and AFTER's in AFTER (.devbin/after).
#   on the H100 or H200:  bash bench/run_two_builds.sh
#   here on lavapipe:     DEVICE= FRAMES=5 WARMUP=1 SIZE=480x270 STRESS_COUNT=8000 BEFORE=... AFTER=build bash bench/run_two_builds.sh
# PARTS ("cost pictures"), CONFIGS ("paper", "wide", "shadows" or "mill"), ROUNDS (2), FRAMES (200), WARMUP (20), SIZE (1920x1080), STRESS_COUNT
# (100000), DEVICE (NVIDIA): part of the device's name, empty for the first device.
set -uo pipefail
source "$(dirname "${BASH_SOURCE[0]}")/lent_machine.sh"
bin=$(realpath "${BEFORE:-.devbin/before}")
after=$(realpath "${AFTER:-.devbin/after}")
parts=${PARTS:-cost pictures}
rounds=${ROUNDS:-2}
frames=${FRAMES:-200}
warmup=${WARMUP:-20}
size=${SIZE:-1920x1080}
stress_count=${STRESS_COUNT:-100000}
device=${DEVICE-NVIDIA}
res=/tmp/two-builds
out=${OUT:-/tmp/out}
begin_run run_two_builds
failures=0

# name: scene flags | method | setting flags
configs=(
  "fig4:--scene paper-fig4:compute:"
  "fig4-nofade:--scene paper-fig4:compute:--lod-fade off"
  "fig4-noshadow:--scene paper-fig4:compute:--shadows off"
  "fig4-twopass:--scene paper-fig4:two-pass:"
  "stress:--scene stress --counts $stress_count --start 20:compute:"
  "stress-nofade:--scene stress --counts $stress_count --start 20:compute:--lod-fade off"
  "default:--scene default:compute:"
)
if [[ ${CONFIGS:-paper} == wide ]]; then
  configs=(
    "cavalry:--scene cavalry:compute:"
    "stress250k:--scene stress --counts 250000 --start 20 --impostors off:compute:"
    "million:--scene stress --counts 1000000 --start 20 --impostors on:compute:"
    "fig4-band5:--scene paper-fig4:compute:--lod-hysteresis 0.05"
    "fig4-vsinst:--scene paper-fig4:vs-instanced:"
  )
elif [[ ${CONFIGS:-paper} == shadows ]]; then
  configs=(
    "stress:--scene stress --counts $stress_count --start 20:compute:"
    "stress-noshadow:--scene stress --counts $stress_count --start 20:compute:--shadows off"
  )
elif [[ ${CONFIGS:-paper} == mill ]]; then
  configs=(
    "mill-inside:--scene stress --counts 1000000 --behaviour mill --start 20 --impostors on:compute:"
    "mill-above:--scene stress --counts 1000000 --behaviour mill --start 30 --impostors on:compute:"
  )
fi

if [[ $parts == *cost* ]]; then
  for round in $(seq "$rounds"); do
    for config in "${configs[@]}"; do
      IFS=: read -r name scene method setting <<<"$config"
      for b in before after; do
        c="$res/bench-$name-$b-$round.csv"
        # shellcheck disable=SC2086  # the flags are words
        run "$name-$b-$round" "$(exe $b crowd-bench)" "${device_flag[@]}" $scene $setting --methods "$method" \
          --frames "$frames" --warmup "$warmup" --size "$size" --csv "$c"
        printf "%-14s %-6s %s | frame %7.3f p95 %7.3f | shadow %6.3f draw %6.3f total %6.3f | lod %s/%s/%s\n" \
          "$name" "$b" "$round" "$(csv_value "$c" median_frame_ms)" "$(csv_value "$c" p95_frame_ms)" \
          "$(csv_value "$c" gpu_shadow_ms)" "$(csv_value "$c" gpu_draw_ms)" "$(csv_value "$c" gpu_total_ms)" \
          "$(csv_value "$c" visible_lod0)" "$(csv_value "$c" visible_lod1)" "$(csv_value "$c" visible_lod2)" | tee -a "$res/summary.txt"
      done
    done
  done
fi

if [[ $parts == *pictures* ]]; then
  for b in before after; do
    for fade in on off; do
      run "picture-$b-$fade" "$(exe $b crowd-render)" "${device_flag[@]}" --scene paper-fig4 --method compute \
        --lod-fade $fade --frames 60 --size "$size" --out "$res/fig4-$b-$fade.png"
    done
  done
  for pair in "before-on after-on" "before-off after-off" "after-off after-on" "before-off before-on"; do
    read -r x y <<<"$pair"
    echo "$x against $y: $("$bin/image-psnr" "$res/fig4-$x.png" "$res/fig4-$y.png" 2>&1)" | tee -a "$res/summary.txt"
  done
  mkdir -p "$out/pics"
  cp "$res"/fig4-*-on.png "$out/pics/" 2>/dev/null
fi

tar -czf "$out/two-builds.tgz" -C /tmp two-builds
echo "failures: $failures"
