#!/usr/bin/env bash
# The characters' sunlight per vertex in compute (var-vsun) against main before it (var-main, four
# shadow-map comparisons a pixel), H100: frames with shadows on and off, fades on and off, the vs
# baseline, and pictures.
# Archived as run; var-vsun was built from branch vertex-sunlight, var-main from main.
set -uo pipefail
bin=$(realpath .devbin); res=/tmp/vsun; out=${OUT:-/tmp/out}; device=NVIDIA
source "$bin/lent_machine.sh"
begin_run vsun
failures=0
echo "commands: crowd-bench <scene> --methods M --shadows on|off [--lod-fade off] --frames 200 --warmup 20 --size 1920x1080 (before: var-main, after: var-vsun)" >"$res/summary.txt"
for round in 1 2; do
  for config in fig4-on fig4-off fig4-on-nofade fig4-off-nofade fig4-vs 100k-on 100k-off default-on stress1m-on; do
    case $config in
      fig4-on) extra=(--scene paper-fig4 --methods compute --shadows on) ;;
      fig4-off) extra=(--scene paper-fig4 --methods compute --shadows off) ;;
      fig4-on-nofade) extra=(--scene paper-fig4 --methods compute --shadows on --lod-fade off) ;;
      fig4-off-nofade) extra=(--scene paper-fig4 --methods compute --shadows off --lod-fade off) ;;
      fig4-vs) extra=(--scene paper-fig4 --methods vs-instanced --shadows on) ;;
      100k-on) extra=(--scene stress --counts 100000 --start 20 --methods compute --shadows on) ;;
      100k-off) extra=(--scene stress --counts 100000 --start 20 --methods compute --shadows off) ;;
      default-on) extra=(--methods compute --shadows on) ;;
      stress1m-on) extra=(--scene stress --counts 1000000 --impostors on --methods compute --shadows on) ;;
    esac
    for v in main vsun; do
      key=$config-$v-$round
      run "$key" "$bin/var-$v/crowd-bench" "${device_flag[@]}" "${extra[@]}" --frames 200 --warmup 20 --size 1920x1080 --csv "$res/$key.csv"
      printf "%-26s | frame %7.3f p95 %7.3f | shadow %6.3f draw %6.3f\n" "$key" "$(csv_value "$res/$key.csv" median_frame_ms)" "$(csv_value "$res/$key.csv" p95_frame_ms)" \
        "$(csv_value "$res/$key.csv" gpu_shadow_ms)" "$(csv_value "$res/$key.csv" gpu_draw_ms)" | tee -a "$res/summary.txt"
    done
  done
done
for v in main vsun; do
  run "pic-$v" "$bin/var-$v/crowd-render" "${device_flag[@]}" --scene paper-fig4 --method compute --frames 30 --size 1920x1080 --out "$res/fig4-$v.png"
  run "pic100k-$v" "$bin/var-$v/crowd-render" "${device_flag[@]}" --scene stress --count 100000 --start 20 --method compute --frames 30 --size 1920x1080 --out "$res/stress100k-$v.png"
  run "picdef-$v" "$bin/var-$v/crowd-render" "${device_flag[@]}" --method compute --frames 30 --size 1920x1080 --out "$res/default-$v.png"
done
for p in fig4 stress100k default; do
  echo "$p vsun against main:" | tee -a "$res/summary.txt"
  "$bin/image-psnr" "$res/$p-main.png" "$res/$p-vsun.png" | tee -a "$res/summary.txt"
done
cp "$res"/*.png "$out/" 2>/dev/null
rm -f "$res"/*.png
tar -czf "$out/vsun.tgz" -C /tmp vsun
echo "failures: $failures"
