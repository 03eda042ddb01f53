#!/usr/bin/env bash
# Where the shadow map's copy goes (X_COPY=depth|keep|colour|none), H100, paper-fig4.
set -uo pipefail
source .devbin/lent_machine.sh
bin=$PWD/.devbin; res=/tmp/cexp; out=${OUT:-/tmp/out}; device=NVIDIA
begin_run copy_exp QUIET
failures=0
for round in 1 2; do
  for scene in paper-fig4 stress100k; do
    extra=(--scene $scene)
    [[ $scene == stress100k ]] && extra=(--scene stress --counts 100000 --start 20)
    for v in depth keep colour none; do
      export X_COPY=$v
      name=$scene-$v-$round
      run "$name" "$bin/var-copy/crowd-bench" "${device_flag[@]}" "${extra[@]}" --methods compute --frames 200 --warmup 20 --size 1920x1080 --csv "$res/$name.csv"
      printf "%-10s %-7s %s | frame %8.3f p95 %8.3f shadow %6.3f draw %6.3f\n" "$scene" "$v" "$round" "$(csv_value "$res/$name.csv" median_frame_ms)" "$(csv_value "$res/$name.csv" p95_frame_ms)" "$(csv_value "$res/$name.csv" gpu_shadow_ms)" "$(csv_value "$res/$name.csv" gpu_draw_ms)" | tee -a "$res/summary.txt"
    done
  done
done
tar -czf "$out/cexp.tgz" -C /tmp cexp
