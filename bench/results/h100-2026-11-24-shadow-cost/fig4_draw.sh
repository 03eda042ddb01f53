#!/usr/bin/env bash
# What paper-fig4's colour pass is bound by: shadows on/off, fades on/off, and a build whose characters'
# fragment shader only writes their albedo (flatchar). 200 frames after 20, two rounds.
set -uo pipefail
bin=$(realpath .devbin); res=/tmp/fig4-draw; out=${OUT:-/tmp/out}; device=NVIDIA
source "$bin/lent_machine.sh"
begin_run fig4_draw
rows=()
for r in 1 2; do for v in new flatchar; do for sh in on off; do for fade in on off; do
  key=$v-sh$sh-fade$fade-$r; rows+=("$key")
  run "$key" "$bin/var-$v/crowd-bench" "${device_flag[@]}" --scene paper-fig4 --methods compute --shadows $sh --lod-fade $fade \
    --frames 200 --warmup 20 --size 1920x1080 --csv "$res/$key.csv"
done; done; done; done
for key in "${rows[@]}"; do c=$res/$key.csv
  printf "%-26s | frame %7.3f | shadow %6.3f draw %6.3f | tris %s\n" "$key" "$(csv_value "$c" median_frame_ms)" \
    "$(csv_value "$c" gpu_shadow_ms)" "$(csv_value "$c" gpu_draw_ms)" "$(csv_value "$c" triangles_drawn)"
done | tee "$res/summary.txt"
tar -czf "$out/fig4-draw.tgz" -C /tmp fig4-draw
