#!/usr/bin/env bash
# paper-fig4, fades on: main (a dither threshold a pixel, discard after the texture read) against
# quad (a threshold a 2x2 quad, discard first); fades off for reference. Two rounds, 200 frames after 20.
set -uo pipefail
source .devbin/lent_machine.sh
bin=$PWD/.devbin; res=/tmp/fadequad; out=${OUT:-/tmp/out}; device=NVIDIA
begin_run fade_quad
variants=("main:crowd-bench:on:paper-fig4" "quad:var-fx/crowd-bench-quad:on:paper-fig4" "off:crowd-bench:off:paper-fig4"
  "main-def:crowd-bench:on:default" "quad-def:var-fx/crowd-bench-quad:on:default")
for round in 1 2 3; do
  for v in "${variants[@]}"; do
    IFS=: read -r name b fade scene <<<"$v"
    c="$res/$name-$round.csv"
    run "$name-$round" "$bin/$b" "${device_flag[@]}" --scene $scene --methods compute --lod-fade $fade --frames 200 --warmup 20 --size 1920x1080 --csv "$c"
    printf "%-9s %s | frame %7.3f p95 %7.3f | shadow %6.3f draw %6.3f | tris %s lod0 %s\n" "$name" "$round" "$(csv_value "$c" median_frame_ms)" "$(csv_value "$c" p95_frame_ms)" "$(csv_value "$c" gpu_shadow_ms)" "$(csv_value "$c" gpu_draw_ms)" "$(csv_value "$c" triangles_drawn)" "$(csv_value "$c" visible_lod0)" | tee -a "$res/summary.txt"
  done
done
nvidia-smi > "$res/nvidia-smi.txt" 2>&1
tar -czf "$out/fadequad.tgz" -C /tmp fadequad
