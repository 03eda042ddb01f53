#!/usr/bin/env bash
# The shadow cost on the README's frames: old main (base, 3c9809b) against this build (new), shadows on
# and off; and two diagnostic builds of it at paper-fig4 whose "copy" pass marks a point inside the
# shadow pass (diagA: after the compute raster; diagB: before the ground sunlight). 200 frames after 20,
# two rounds interleaved.
set -uo pipefail
bin=$(realpath .devbin); res=/tmp/shadow-final; out=${OUT:-/tmp/out}; device=NVIDIA
source "$bin/lent_machine.sh"
begin_run shadow_final
scenes=("fig4:--scene paper-fig4" "default:--scene default" "stress100k-in:--scene stress --counts 100000 --start 20")
rows=()
for round in 1 2; do for s in "${scenes[@]}"; do name=${s%%:*}; read -r -a flags <<<"${s#*:}"
  for v in base new; do for sh in on off; do
    [[ $v == diag* && ( $name != fig4 || $sh == off ) ]] && continue
    key=$name-$v-$sh-$round; rows+=("$key")
    run "$key" "$bin/var-$v/crowd-bench" "${device_flag[@]}" "${flags[@]}" --methods compute --shadows $sh \
      --frames 200 --warmup 20 --size 1920x1080 --csv "$res/$key.csv"
  done; done
done; done
printf "%-32s | %8s %8s %7s | %8s %8s %8s %8s\n" run frame p95 fps copy shadow draw raster
for key in "${rows[@]}"; do c=$res/$key.csv
  printf "%-32s | %8.3f %8.3f %7.1f | %8.3f %8.3f %8.3f %8.3f\n" "$key" "$(csv_value "$c" median_frame_ms)" \
    "$(csv_value "$c" p95_frame_ms)" "$(csv_value "$c" fps)" "$(csv_value "$c" gpu_copy_ms)" "$(csv_value "$c" gpu_shadow_ms)" \
    "$(csv_value "$c" gpu_draw_ms)" "$(csv_value "$c" gpu_raster_ms)"
done | tee "$res/summary.txt"
tar -czf "$out/shadow-final.tgz" -C /tmp shadow-final
