#!/usr/bin/env bash
# Archived as run; the variants were built from branch vertex-sunlight (var-vsun, var-vsunA) and main.
set -uo pipefail
bin=$(realpath .devbin); res=/tmp/vsunA; out=${OUT:-/tmp/out}; device=NVIDIA
source "$bin/lent_machine.sh"
begin_run vsunA QUIET
failures=0
for round in 1 2; do
  for config in fig4-on fig4-off fig4-on-nofade 100k-on 100k-off; do
    case $config in
      fig4-on) extra=(--scene paper-fig4 --methods compute --shadows on) ;;
      fig4-off) extra=(--scene paper-fig4 --methods compute --shadows off) ;;
      fig4-on-nofade) extra=(--scene paper-fig4 --methods compute --shadows on --lod-fade off) ;;
      100k-on) extra=(--scene stress --counts 100000 --start 20 --methods compute --shadows on) ;;
      100k-off) extra=(--scene stress --counts 100000 --start 20 --methods compute --shadows off) ;;
    esac
    for v in main vsunA; do
      key=$config-$v-$round
      run "$key" "$bin/var-$v/crowd-bench" "${device_flag[@]}" "${extra[@]}" --frames 200 --warmup 20 --size 1920x1080 --csv "$res/$key.csv" >/dev/null
      printf "%-26s | frame %7.3f p95 %7.3f | shadow %6.3f draw %6.3f\n" "$key" "$(csv_value "$res/$key.csv" median_frame_ms)" "$(csv_value "$res/$key.csv" p95_frame_ms)" \
        "$(csv_value "$res/$key.csv" gpu_shadow_ms)" "$(csv_value "$res/$key.csv" gpu_draw_ms)" | tee -a "$res/summary.txt"
    done
  done
done
"$bin/var-vsunA/crowd-render" "${device_flag[@]}" --scene paper-fig4 --method compute --frames 30 --size 1920x1080 --out "$res/fig4-vsunA.png" >/dev/null
"$bin/var-main/crowd-render" "${device_flag[@]}" --scene paper-fig4 --method compute --frames 30 --size 1920x1080 --out "$res/fig4-main.png" >/dev/null
"$bin/image-psnr" "$res/fig4-main.png" "$res/fig4-vsunA.png" | tee -a "$res/summary.txt"
cp "$res/summary.txt" "$out/"
