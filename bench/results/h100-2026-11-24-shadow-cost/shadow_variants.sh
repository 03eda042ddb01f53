#!/usr/bin/env bash
# Where paper-fig4's shadow cost goes: the same frame with builds whose shaders differ (base; sunlight one
# tap instead of nine; ground not lit; ground a constant colour), shadows on and off, 200 frames after 20,
# two rounds interleaved.
set -uo pipefail
bin=$(realpath .devbin); res=/tmp/shadow-variants; out=${OUT:-/tmp/out}; device=NVIDIA
source "$bin/lent_machine.sh"
begin_run shadow_variants
vars=(base onetap groundflat groundconst)
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
tar -czf "$out/shadow-variants.tgz" -C /tmp shadow-variants
