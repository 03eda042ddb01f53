#!/usr/bin/env bash
# Shadows on and off, before and after the ground behind the characters (var-new), H100.
set -uo pipefail
source .devbin/lent_machine.sh
bin=$PWD/.devbin; res=/tmp/gshadow; out=${OUT:-/tmp/out}; device=NVIDIA
begin_run ground_shadowcost QUIET
failures=0
for round in 1 2; do
  for scene in paper-fig4 stress100k default; do
    extra=(--scene $scene)
    [[ $scene == stress100k ]] && extra=(--scene stress --counts 100000 --start 20)
    for sh in on off; do
      for v in before after afternofade; do
        b=$bin; [[ $v == after* ]] && b=$bin/var-new
        fx=(); [[ $v == afternofade ]] && fx=(--lod-fade off)
        [[ $v == afternofade && $scene != paper-fig4 ]] && continue
        name=$scene-$sh-$v-$round
        run "$name" "$b/crowd-bench" "${device_flag[@]}" "${extra[@]}" "${fx[@]}" --shadows $sh --methods compute --frames 200 --warmup 20 --size 1920x1080 --csv "$res/$name.csv"
        printf "%-10s shadows %-3s %-11s %s | frame %8.3f p95 %8.3f shadow %6.3f draw %6.3f\n" "$scene" "$sh" "$v" "$round" "$(csv_value "$res/$name.csv" median_frame_ms)" "$(csv_value "$res/$name.csv" p95_frame_ms)" "$(csv_value "$res/$name.csv" gpu_shadow_ms)" "$(csv_value "$res/$name.csv" gpu_draw_ms)" | tee -a "$res/summary.txt"
      done
    done
  done
done
tar -czf "$out/gshadow.tgz" -C /tmp gshadow
