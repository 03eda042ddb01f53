#!/usr/bin/env bash
# paper-fig4 with fades across bands of 10 % (the default), 5 % and 2.5 % of the thresholds, and off;
# three rounds, 200 frames after 20, 1920x1080, compute, shadows on.
set -uo pipefail
source .devbin/lent_machine.sh
bin=$PWD/.devbin; res=/tmp/fadeband; out=${OUT:-/tmp/out}; device=NVIDIA
begin_run fade_band
variants=("band10:on:0.1" "band5:on:0.05" "band2.5:on:0.025" "off:off:0.1")
for round in 1 2 3; do
  for v in "${variants[@]}"; do
    IFS=: read -r name fade band <<<"$v"
    c="$res/$name-$round.csv"
    run "$name-$round" "$bin/crowd-bench" "${device_flag[@]}" --scene paper-fig4 --methods compute --lod-fade $fade --lod-hysteresis $band --frames 200 --warmup 20 --size 1920x1080 --csv "$c"
    printf "%-8s %s | frame %7.3f p95 %7.3f | shadow %6.3f draw %6.3f | tris %s lod0 %s\n" "$name" "$round" "$(csv_value "$c" median_frame_ms)" "$(csv_value "$c" p95_frame_ms)" "$(csv_value "$c" gpu_shadow_ms)" "$(csv_value "$c" gpu_draw_ms)" "$(csv_value "$c" triangles_drawn)" "$(csv_value "$c" visible_lod0)" | tee -a "$res/summary.txt"
  done
done
nvidia-smi > "$res/nvidia-smi.txt" 2>&1
tar -czf "$out/fadeband.tgz" -C /tmp fadeband
