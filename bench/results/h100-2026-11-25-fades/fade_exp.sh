#!/usr/bin/env bash
# Where paper-fig4's fade cost goes: main with fades on and off; var-fx (X_FADE=skipboth: the fading
# characters not drawn; fineronly: their finer level only, dithered; finernodiscard: their finer level
# only, whole, no discard); var-ez (the character shader with early fragment tests forced).
set -uo pipefail
source .devbin/lent_machine.sh
bin=$PWD/.devbin; res=/tmp/fadeexp; out=${OUT:-/tmp/out}; device=NVIDIA
begin_run fade_exp
variants=("main:crowd-bench::on" "mainoff:crowd-bench::off" "skip:var-fx/crowd-bench:skipboth:on"
  "finer:var-fx/crowd-bench:fineronly:on" "finerwhole:var-fx/crowd-bench:finernodiscard:on" "early:var-ez/crowd-bench::on")
for round in 1 2; do
  for v in "${variants[@]}"; do
    IFS=: read -r name b xf fade <<<"$v"
    export X_FADE=$xf
    c="$res/$name-$round.csv"
    run "$name-$round" "$bin/$b" "${device_flag[@]}" --scene paper-fig4 --methods compute --lod-fade $fade --frames 200 --warmup 20 --size 1920x1080 --csv "$c"
    printf "%-10s %s | frame %7.3f p95 %7.3f | shadow %6.3f draw %6.3f | tris %s lod0 %s\n" "$name" "$round" "$(csv_value "$c" median_frame_ms)" "$(csv_value "$c" p95_frame_ms)" "$(csv_value "$c" gpu_shadow_ms)" "$(csv_value "$c" gpu_draw_ms)" "$(csv_value "$c" triangles_drawn)" "$(csv_value "$c" visible_lod0)" | tee -a "$res/summary.txt"
  done
done
tar -czf "$out/fadeexp.tgz" -C /tmp fadeexp
