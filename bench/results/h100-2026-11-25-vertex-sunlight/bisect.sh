#!/usr/bin/env bash
# Archived as run; the variants were built from branch vertex-sunlight (var-vsun, var-vsunA) and main.
set -uo pipefail
bin=$(realpath .devbin); res=/tmp/bisect; out=${OUT:-/tmp/out}; device=NVIDIA
source "$bin/lent_machine.sh"
begin_run bisect QUIET
failures=0
for round in 1 2; do
  for config in fig4-off fig4-on; do
    case $config in
      fig4-on) extra=(--scene paper-fig4 --methods compute --shadows on) ;;
      fig4-off) extra=(--scene paper-fig4 --methods compute --shadows off) ;;
    esac
    for v in main d1 d2 vsunA; do
      key=$config-$v-$round
      run "$key" "$bin/var-$v/crowd-bench" "${device_flag[@]}" "${extra[@]}" --frames 200 --warmup 20 --size 1920x1080 --csv "$res/$key.csv" >/dev/null
      printf "%-26s | frame %7.3f p95 %7.3f | shadow %6.3f draw %6.3f\n" "$key" "$(csv_value "$res/$key.csv" median_frame_ms)" "$(csv_value "$res/$key.csv" p95_frame_ms)" \
        "$(csv_value "$res/$key.csv" gpu_shadow_ms)" "$(csv_value "$res/$key.csv" gpu_draw_ms)" | tee -a "$res/summary.txt"
    done
  done
done
cp "$res/summary.txt" "$out/"
