#!/usr/bin/env bash
# DIAG: the triangle filter prototype (CROWD_TRIANGLE_FILTER=<capacity in triangles>) against none, one binary.
set -uo pipefail
bin=$(realpath .devbin); res=/tmp/filter; out=${OUT:-/tmp/out}; device=NVIDIA
source "$bin/lent_machine.sh"
begin_run filter_exp
for r in 1 2; do for scene in paper-fig4 stress100k default fig4-noshadow; do for v in off on; do
  extra=(--scene $scene)
  [[ $scene == stress100k ]] && extra=(--scene stress --counts 100000 --start 20)
  [[ $scene == fig4-noshadow ]] && extra=(--scene paper-fig4 --shadows off)
  key=$scene-$v-$r
  if [[ $v == on ]]; then export CROWD_TRIANGLE_FILTER=8000000; else unset CROWD_TRIANGLE_FILTER; fi
  run "$key" "$bin/var-filter/crowd-bench" "${device_flag[@]}" "${extra[@]}" --methods compute --frames 200 --warmup 20 --size 1920x1080 --csv "$res/$key.csv" --json "$res/$key.json"
  printf "%-24s | frame %7.3f p95 %7.3f | shadow %6.3f draw %6.3f | %s\n" "$key" "$(csv_value "$res/$key.csv" median_frame_ms)" "$(csv_value "$res/$key.csv" p95_frame_ms)" \
    "$(csv_value "$res/$key.csv" gpu_shadow_ms)" "$(csv_value "$res/$key.csv" gpu_draw_ms)" "$(grep -o '"filter": [0-9.]*' "$res/$key.json" | head -1)" | tee -a "$res/summary.txt"
done; done; done
unset CROWD_TRIANGLE_FILTER
run pic-off "$bin/var-filter/crowd-render" "${device_flag[@]}" --scene paper-fig4 --method compute --frames 30 --size 1920x1080 --out "$res/fig4-off.png"
CROWD_TRIANGLE_FILTER=8000000 run pic-on "$bin/var-filter/crowd-render" "${device_flag[@]}" --scene paper-fig4 --method compute --frames 30 --size 1920x1080 --out "$res/fig4-on.png"
"$bin/image-psnr" "$res/fig4-off.png" "$res/fig4-on.png" | tee -a "$res/summary.txt"
rm -f "$res"/*.png
tar -czf "$out/filter.tgz" -C /tmp filter
