#!/usr/bin/env bash
# The shadow cost after the compute raster's depth copy and the ground sunlight image: old main (base)
# against the new build with the characters' sunlight from nine, four or one comparisons.
# two rounds interleaved.
set -uo pipefail
bin=$(realpath .devbin); res=/tmp/shadow-variants2; out=${OUT:-/tmp/out}; device=NVIDIA
source "$bin/lent_machine.sh"
begin_run shadow_variants2
vars=(base char9 char4 char1)
scenes=("fig4:--scene paper-fig4" "stress100k-in:--scene stress --counts 100000 --start 20")
for round in 1 2; do for s in "${scenes[@]}"; do name=${s%%:*}; read -r -a flags <<<"${s#*:}"
  for v in "${vars[@]}"; do for sh in on off; do
    run "$name-$v-$sh-$round" "$bin/var-$v/crowd-bench" "${device_flag[@]}" "${flags[@]}" --methods compute --shadows $sh \
      --frames 200 --warmup 20 --size 1920x1080 --csv "$res/$name-$v-$sh-$round.csv"
  done; done
done; done
printf "%-14s %-12s %3s %2s | %8s %8s | %8s %8s %8s\n" scene variant sh r frame p95 shadow draw skin
for round in 1 2; do for s in "${scenes[@]}"; do name=${s%%:*}; for v in "${vars[@]}"; do for sh in on off; do
  c=$res/$name-$v-$sh-$round.csv
  printf "%-14s %-12s %3s %2s | %8.3f %8.3f | %8.3f %8.3f %8.3f\n" "$name" "$v" "$sh" "$round" "$(csv_value "$c" median_frame_ms)" \
    "$(csv_value "$c" p95_frame_ms)" "$(csv_value "$c" gpu_shadow_ms)" "$(csv_value "$c" gpu_draw_ms)" "$(csv_value "$c" gpu_skin_ms)"
done; done; done; done | tee "$res/summary.txt"
head -1 $res/fig4-base-on-1.csv
tar -czf "$out/shadow-variants2.tgz" -C /tmp shadow-variants2
