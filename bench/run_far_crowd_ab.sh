#!/usr/bin/env bash
# Two builds of the far crowd compared on a lent GPU machine (stress from above with impostors, one
# sample a pixel, compute skinning, 1920x1080): BEFORE's and AFTER's binaries.
# 1. Cost (PARTS has "cost"): crowd-bench on 1,000,000 and 10,000,000 soldiers, from above and inside
#    (--start 20), shadows on, mesh capacity 65,536, 60 frames after 10, both builds interleaved in
#    ROUNDS rounds: median and p95 frame, the raster pass, the colour pass, the GPU total.
# 2. Pictures (PARTS has "pictures"): the 5th and 30th frames of 1,000,000 at 1920x1080 against the 4x4
#    supersampled impostor render (--far-crowd off at 7680x4320, box-filtered down by image-downsample),
#    and of 250,000 at 960x540 against that and the 4x4 supersampled mesh render (--impostors off),
#    each build's and --far-crowd off's, compared by image-psnr; the 5th frame of 1,000,000 of each
#    build and the reference land in $OUT/pics.
# Writes $OUT/far-crowd-ab.tgz (every run's output, CSV and summary).
#
# Expects the Vulkan loader packages in .gl/, the binaries (crowd-bench, crowd-render, image-psnr,
# image-downsample, with their shared libraries) in BEFORE (.devbin) and AFTER's crowd-bench and
# crowd-render in AFTER (no default: say which).
#   on the H100:  AFTER=.devbin/var-whole bash bench/run_far_crowd_ab.sh
# PARTS ("cost pictures"), ROUNDS (2), DEVICE (NVIDIA): part of the device's name.
set -uo pipefail
source "$(dirname "${BASH_SOURCE[0]}")/lent_machine.sh"
bin=$(realpath "${BEFORE:-.devbin}")
after=$(realpath "${AFTER:?AFTER names the folder of the second build}")
parts=${PARTS:-cost pictures}
rounds=${ROUNDS:-2}
device=${DEVICE-NVIDIA}
res=/tmp/far-crowd-ab
out=${OUT:-/tmp/out}
begin_run run_far_crowd_ab
failures=0

if [[ $parts == *cost* ]]; then
  for round in $(seq "$rounds"); do
    for v in "10000000:above" "10000000:inside" "1000000:above" "1000000:inside"; do
      IFS=: read -r n cam <<<"$v"; start=0; [[ $cam == inside ]] && start=20
      for b in before after; do
        c="$res/bench-$n-$cam-$b-$round.csv"
        run "$n-$cam-$b-$round" "$(exe $b crowd-bench)" "${device_flag[@]}" --scene stress --counts $n --models soldier \
          --start $start --impostors on --mesh-capacity 65536 --shadows on --methods compute --frames 60 --warmup 10 \
          --size 1920x1080 --csv "$c"
        printf "%-8s %-6s %-6s %s | frame %7.3f p95 %7.3f | raster %6.3f draw %6.3f total %6.3f\n" "$n" "$cam" "$b" "$round" \
          "$(csv_value "$c" median_frame_ms)" "$(csv_value "$c" p95_frame_ms)" "$(csv_value "$c" gpu_raster_ms)" \
          "$(csv_value "$c" gpu_draw_ms)" "$(csv_value "$c" gpu_total_ms)" | tee -a "$res/summary.txt"
      done
    done
  done
fi

if [[ $parts == *pictures* ]]; then
  for spec in "1000000:1920x1080:7680x4320:5" "1000000:1920x1080:7680x4320:30" "250000:960x540:3840x2160:5" "250000:960x540:3840x2160:30"; do
    IFS=: read -r n size big f <<<"$spec"
    B=(--scene stress --count $n --method compute --aa off --start 0 --frames $f)
    run "imp4-$n-$f" "$after/crowd-render" "${device_flag[@]}" "${B[@]}" --impostors on --far-crowd off --size $big --out "$res/big.png" &&
      "$bin/image-downsample" "$res/big.png" 4 "$res/imp-$n-$f.png"
    rm -f "$res/big.png"
    refs=(imp)
    if [[ $n == 250000 ]]; then
      run "mesh4-$n-$f" "$after/crowd-render" "${device_flag[@]}" "${B[@]}" --impostors off --size $big --out "$res/big.png" &&
        "$bin/image-downsample" "$res/big.png" 4 "$res/mesh-$n-$f.png"
      rm -f "$res/big.png"
      refs=(imp mesh)
    fi
    for b in before after off; do
      far=(); program=$(exe $b crowd-render)
      [[ $b == off ]] && far=(--far-crowd off) && program=$after/crowd-render
      run "pic-$n-$f-$b" "$program" "${device_flag[@]}" "${B[@]}" --impostors on "${far[@]}" --size $size --out "$res/$b-$n-$f.png"
      for r in "${refs[@]}"; do
        echo "$n frame $f $b vs $r: $("$bin/image-psnr" "$res/$r-$n-$f.png" "$res/$b-$n-$f.png")" | tee -a "$res/summary.txt"
      done
    done
  done
  mkdir -p "$out/pics"
  for f in before after imp; do cp "$res/$f-1000000-5.png" "$out/pics/" 2>/dev/null; done
  rm -f "$res"/*.png
fi
tar -czf "$out/far-crowd-ab.tgz" -C /tmp far-crowd-ab
echo "run_far_crowd_ab: $failures failed runs"
