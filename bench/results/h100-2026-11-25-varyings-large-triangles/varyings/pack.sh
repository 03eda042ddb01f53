#!/usr/bin/env bash
# Fewer interpolated values in the characters' colour pass, H100: main (13 components: normal, albedo,
# world, uv, slot, fade share), pack (10: albedo, slot and share in one flat pair of halves and bytes),
# world (7: that, and the world position from the fragment's depth instead of a varying).
set -uo pipefail
bin=$(realpath .devbin); res=/tmp/pack; out=${OUT:-/tmp/out}; device=NVIDIA
source "$bin/lent_machine.sh"
begin_run pack
failures=0
variants=(${VARIANTS:-main pack world})
echo "commands: crowd-bench <scene> --methods M --shadows on|off [--lod-fade off] --frames 200 --warmup 20 --size 1920x1080 (var-main, var-pack, var-world)" >"$res/summary.txt"
for round in 1 2; do
  for config in ${CONFIGS:-fig4-on fig4-on-nofade fig4-off 100k-on default-on fig4-vs}; do
    case $config in
      fig4-on) extra=(--scene paper-fig4 --methods compute --shadows on) ;;
      fig4-off) extra=(--scene paper-fig4 --methods compute --shadows off) ;;
      fig4-on-nofade) extra=(--scene paper-fig4 --methods compute --shadows on --lod-fade off) ;;
      fig4-vs) extra=(--scene paper-fig4 --methods vs-instanced --shadows on) ;;
      100k-on) extra=(--scene stress --counts 100000 --start 20 --methods compute --shadows on) ;;
      default-on) extra=(--methods compute --shadows on) ;;
    esac
    for v in "${variants[@]}"; do
      key=$config-$v-$round
      run "$key" "$bin/var-$v/crowd-bench" "${device_flag[@]}" "${extra[@]}" --frames 200 --warmup 20 --size 1920x1080 --csv "$res/$key.csv"
      printf "%-26s | frame %7.3f p95 %7.3f | shadow %6.3f draw %6.3f\n" "$key" "$(csv_value "$res/$key.csv" median_frame_ms)" "$(csv_value "$res/$key.csv" p95_frame_ms)" \
        "$(csv_value "$res/$key.csv" gpu_shadow_ms)" "$(csv_value "$res/$key.csv" gpu_draw_ms)" | tee -a "$res/summary.txt"
    done
  done
done
tar -czf "$out/pack.tgz" -C /tmp pack
echo "failures: $failures"
