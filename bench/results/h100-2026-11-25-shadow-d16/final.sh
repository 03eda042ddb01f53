#!/usr/bin/env bash
# main (1bbdcca): the milling crowd's p95 (bench/run_planning.sh) and the hardware shadow raster with the 16-bit map.
set -uo pipefail
OUT=${OUT:-/tmp/out} bash bench/run_planning.sh 2>&1 | grep -v "^==" | tee "$OUT/planning.txt"
bin=$(realpath .devbin); res=/tmp/hwshadow; out=${OUT:-/tmp/out}; device=NVIDIA
source "$bin/lent_machine.sh"
begin_run hwshadow QUIET
for r in 1 2; do for sr in compute hardware; do
  key=fig4-$sr-$r
  run "$key" "$bin/crowd-bench" "${device_flag[@]}" --scene paper-fig4 --methods compute --shadow-raster $sr --frames 200 --warmup 20 --size 1920x1080 --csv "$res/$key.csv"
  printf "%-22s | frame %7.3f | shadow %6.3f draw %6.3f\n" "$key" "$(csv_value "$res/$key.csv" median_frame_ms)" "$(csv_value "$res/$key.csv" gpu_shadow_ms)" "$(csv_value "$res/$key.csv" gpu_draw_ms)" | tee -a "$res/summary.txt"
done; done
for sr in compute hardware; do run "pic-$sr" "$bin/crowd-render" "${device_flag[@]}" --scene paper-fig4 --method compute --shadow-raster $sr --frames 30 --size 1920x1080 --out "$res/fig4-$sr.png"; done
"$bin/image-psnr" "$res/fig4-hardware.png" "$res/fig4-compute.png" | tee -a "$res/summary.txt"
cp "$res/fig4-hardware.png" "$out/" ; rm -f "$res"/*.png
tar -czf "$out/hwshadow.tgz" -C /tmp hwshadow
