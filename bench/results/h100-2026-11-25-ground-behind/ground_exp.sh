#!/usr/bin/env bash
# Ground cost experiment: exp crowd-bench (X_GROUND=first|last|none) on fig4, default, stress 100k inside.
set -uo pipefail
source .devbin/lent_machine.sh
bin=$PWD/.devbin; res=/tmp/gexp; out=${OUT:-/tmp/out}; device=NVIDIA
begin_run ground_exp
failures=0
for round in 1 2; do
  for scene in paper-fig4 default; do
    extra=(); [[ $scene == stress ]] && extra=(--counts 100000 --start 20)
    for g in first last none lastnofade; do
      fx=(); [[ $g == lastnofade ]] && fx=(--lod-fade off)
      export X_GROUND=${g%nofade}; run "$scene-$g-$round" "$bin/var-exp/crowd-bench" "${device_flag[@]}" --scene $scene "${extra[@]}" "${fx[@]}" --methods compute --frames 150 --warmup 20 --size 1920x1080 --csv "$res/$scene-$g-$round.csv"
      printf "%-10s %-5s %s | frame %8.3f p95 %8.3f shadow %6.3f draw %6.3f\n" "$scene" "$g" "$round" "$(csv_value "$res/$scene-$g-$round.csv" median_frame_ms)" "$(csv_value "$res/$scene-$g-$round.csv" p95_frame_ms)" "$(csv_value "$res/$scene-$g-$round.csv" gpu_shadow_ms)" "$(csv_value "$res/$scene-$g-$round.csv" gpu_draw_ms)" | tee -a "$res/summary.txt"
    done
  done
done
for g in first last none; do export X_GROUND=$g; run "pic-$g" "$bin/var-exp/crowd-render" "${device_flag[@]}" --scene paper-fig4 --method compute --frames 30 --size 1920x1080 --out "$res/fig4-$g.png"; done
"$bin/image-psnr" "$res/fig4-first.png" "$res/fig4-last.png" | tee -a "$res/summary.txt"
"$bin/image-psnr" "$res/fig4-first.png" "$res/fig4-none.png" | tee -a "$res/summary.txt"
tar -czf "$out/gexp.tgz" -C /tmp gexp
