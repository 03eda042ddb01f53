#!/usr/bin/env bash
# The shadow map in 16 bits (var-d16) against main before it (var-main), H100: frames with shadows on
# and off, and pictures.
set -uo pipefail
bin=$(realpath .devbin); res=/tmp/d16; out=${OUT:-/tmp/out}; device=NVIDIA
source "$bin/lent_machine.sh"
begin_run d16
failures=0
echo "commands: crowd-bench <scene> --methods compute --shadows on|off --frames 200 --warmup 20 --size 1920x1080 (before: var-main = c8fc40d, after: var-d16)" >"$res/summary.txt"
for round in 1 2; do
  for scene in paper-fig4 stress100k default stress1m; do
    extra=(--scene $scene)
    [[ $scene == stress100k ]] && extra=(--scene stress --counts 100000 --start 20)
    [[ $scene == stress1m ]] && extra=(--scene stress --counts 1000000 --impostors on)
    for sh in on off; do
      [[ $scene == stress1m || $scene == default ]] && [[ $sh == off ]] && continue
      for v in main d16; do
        key=$scene-sh$sh-$v-$round
        run "$key" "$bin/var-$v/crowd-bench" "${device_flag[@]}" "${extra[@]}" --methods compute --shadows $sh --frames 200 --warmup 20 --size 1920x1080 --csv "$res/$key.csv"
        printf "%-28s | frame %7.3f p95 %7.3f | shadow %6.3f draw %6.3f\n" "$key" "$(csv_value "$res/$key.csv" median_frame_ms)" "$(csv_value "$res/$key.csv" p95_frame_ms)" \
          "$(csv_value "$res/$key.csv" gpu_shadow_ms)" "$(csv_value "$res/$key.csv" gpu_draw_ms)" | tee -a "$res/summary.txt"
      done
    done
  done
done
for v in main d16; do
  run "pic-$v" "$bin/var-$v/crowd-render" "${device_flag[@]}" --scene paper-fig4 --method compute --frames 30 --size 1920x1080 --out "$res/fig4-$v.png"
  run "pic100k-$v" "$bin/var-$v/crowd-render" "${device_flag[@]}" --scene stress --count 100000 --start 20 --method compute --frames 30 --size 1920x1080 --out "$res/stress100k-$v.png"
  run "picdef-$v" "$bin/var-$v/crowd-render" "${device_flag[@]}" --method compute --frames 30 --size 1920x1080 --out "$res/default-$v.png"
done
for p in fig4 stress100k default; do
  echo "$p d16 against main:" | tee -a "$res/summary.txt"
  "$bin/image-psnr" "$res/$p-main.png" "$res/$p-d16.png" | tee -a "$res/summary.txt"
done
tar -czf "$out/d16.tgz" -C /tmp d16
