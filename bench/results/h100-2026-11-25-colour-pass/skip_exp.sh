#!/usr/bin/env bash
# Untextured materials fetch no texture and no coordinates (var-skip) against main (var-main), H100.
set -uo pipefail
bin=$(realpath .devbin); res=/tmp/skip; out=${OUT:-/tmp/out}; device=NVIDIA
source "$bin/lent_machine.sh"
begin_run skip_exp
echo "commands: crowd-bench <scene> --methods compute --shadows on|off --frames 200 --warmup 20 --size 1920x1080 (before: var-main, after: var-skip)" >"$res/summary.txt"
for r in 1 2; do for scene in paper-fig4 fig4-noshadow stress100k default stress1m; do for v in main skip; do
  extra=(--scene $scene)
  [[ $scene == stress100k ]] && extra=(--scene stress --counts 100000 --start 20)
  [[ $scene == stress1m ]] && extra=(--scene stress --counts 1000000 --impostors on)
  [[ $scene == fig4-noshadow ]] && extra=(--scene paper-fig4 --shadows off)
  key=$scene-$v-$r
  run "$key" "$bin/var-$v/crowd-bench" "${device_flag[@]}" "${extra[@]}" --methods compute --frames 200 --warmup 20 --size 1920x1080 --csv "$res/$key.csv"
  printf "%-22s | frame %7.3f p95 %7.3f | shadow %6.3f draw %6.3f\n" "$key" "$(csv_value "$res/$key.csv" median_frame_ms)" "$(csv_value "$res/$key.csv" p95_frame_ms)" \
    "$(csv_value "$res/$key.csv" gpu_shadow_ms)" "$(csv_value "$res/$key.csv" gpu_draw_ms)" | tee -a "$res/summary.txt"
done; done; done
for v in main skip; do
  run "pic-$v" "$bin/var-$v/crowd-render" "${device_flag[@]}" --scene paper-fig4 --method compute --frames 30 --size 1920x1080 --out "$res/fig4-$v.png"
  run "pic100k-$v" "$bin/var-$v/crowd-render" "${device_flag[@]}" --scene stress --count 100000 --start 20 --method compute --frames 30 --size 1920x1080 --out "$res/s100k-$v.png"
done
for p in fig4 s100k; do echo "$p skip against main:" | tee -a "$res/summary.txt"; "$bin/image-psnr" "$res/$p-main.png" "$res/$p-skip.png" | tee -a "$res/summary.txt"; done
rm -f "$res"/*.png
tar -czf "$out/skip.tgz" -C /tmp skip
