#!/usr/bin/env bash
# DIAG: what paper-fig4's colour pass is bound by: main, a vertex shader with no per-character reads
# (thinvs), and that with a flat fragment shader (thinall); shadows on and off, fades on and off.
set -uo pipefail
bin=$(realpath .devbin); res=/tmp/vsexp; out=${OUT:-/tmp/out}; device=NVIDIA
source "$bin/lent_machine.sh"
begin_run vs_exp
for r in 1 2; do for sh in on off; do for fade in on off; do for v in main thinvs thinall; do
  key=$v-sh$sh-fade$fade-$r
  run "$key" "$bin/var-$v/crowd-bench" "${device_flag[@]}" --scene paper-fig4 --methods compute --shadows $sh --lod-fade $fade --frames 200 --warmup 20 --size 1920x1080 --csv "$res/$key.csv"
  printf "%-24s | frame %7.3f | shadow %6.3f draw %6.3f | tris %s\n" "$key" "$(csv_value "$res/$key.csv" median_frame_ms)" \
    "$(csv_value "$res/$key.csv" gpu_shadow_ms)" "$(csv_value "$res/$key.csv" gpu_draw_ms)" "$(csv_value "$res/$key.csv" triangles_drawn)" | tee -a "$res/summary.txt"
done; done; done; done
tar -czf "$out/vsexp.tgz" -C /tmp vsexp
