#!/usr/bin/env bash
# DIAG: fragment invocations of the character draws and the ground (pipeline statistics), and the colour
# pass with each bucket's draw list in reverse order (var-rev) against as culled (var-stats); the copy micro.
set -uo pipefail
bin=$(realpath .devbin); res=/tmp/order; out=${OUT:-/tmp/out}; device=NVIDIA
source "$bin/lent_machine.sh"
begin_run order_exp
"$bin/copy_micro" > "$res/copy_micro.txt" 2>&1; cat "$res/copy_micro.txt"
for r in 1 2; do for scene in paper-fig4 stress100k default; do for v in stats rev; do
  extra=(--scene $scene)
  [[ $scene == stress100k ]] && extra=(--scene stress --counts 100000 --start 20)
  key=$scene-$v-$r
  run "$key" "$bin/var-$v/crowd-bench" "${device_flag[@]}" "${extra[@]}" --methods compute --frames 200 --warmup 20 --size 1920x1080 --csv "$res/$key.csv"
  printf "%-22s | frame %7.3f | shadow %6.3f draw %6.3f | %s\n" "$key" "$(csv_value "$res/$key.csv" median_frame_ms)" \
    "$(csv_value "$res/$key.csv" gpu_shadow_ms)" "$(csv_value "$res/$key.csv" gpu_draw_ms)" "$(grep DIAG "$res/$key.txt")" | tee -a "$res/summary.txt"
done; done; done
tar -czf "$out/order.tgz" -C /tmp order
