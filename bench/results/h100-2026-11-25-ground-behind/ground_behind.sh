#!/usr/bin/env bash
# The ground behind the characters (RendererSettings::ground, var-new) against main before it (.devbin), H100.
set -uo pipefail
source .devbin/lent_machine.sh
bin=$PWD/.devbin; res=/tmp/gbehind; out=${OUT:-/tmp/out}; device=NVIDIA
begin_run ground_behind
failures=0
echo "commands: crowd-bench <scene> --methods compute --frames 200 --warmup 20 --size 1920x1080 (before: .devbin, after: .devbin/var-new)" >"$res/summary.txt"
for round in 1 2; do
  for scene in paper-fig4 default stress100k stress1m; do
    extra=(--scene $scene)
    [[ $scene == stress100k ]] && extra=(--scene stress --counts 100000 --start 20)
    [[ $scene == stress1m ]] && extra=(--scene stress --counts 1000000 --impostors on)
    for v in before after; do
      b=$bin; [[ $v == after ]] && b=$bin/var-new
      run "$scene-$v-$round" "$b/crowd-bench" "${device_flag[@]}" "${extra[@]}" --methods compute --frames 200 --warmup 20 --size 1920x1080 --csv "$res/$scene-$v-$round.csv"
      printf "%-10s %-6s %s | frame %8.3f p95 %8.3f shadow %6.3f draw %6.3f\n" "$scene" "$v" "$round" "$(csv_value "$res/$scene-$v-$round.csv" median_frame_ms)" "$(csv_value "$res/$scene-$v-$round.csv" p95_frame_ms)" "$(csv_value "$res/$scene-$v-$round.csv" gpu_shadow_ms)" "$(csv_value "$res/$scene-$v-$round.csv" gpu_draw_ms)" | tee -a "$res/summary.txt"
    done
  done
done
for v in before after; do
  b=$bin; [[ $v == after ]] && b=$bin/var-new
  run "pic-$v" "$b/crowd-render" "${device_flag[@]}" --scene paper-fig4 --method compute --frames 30 --size 1920x1080 --out "$res/fig4-$v.png"
  run "pic1m-$v" "$b/crowd-render" "${device_flag[@]}" --scene stress --count 1000000 --impostors on --method compute --frames 30 --size 1920x1080 --out "$res/stress1m-$v.png"
done
echo "paper-fig4 after against before:" | tee -a "$res/summary.txt"
"$bin/image-psnr" "$res/fig4-before.png" "$res/fig4-after.png" | tee -a "$res/summary.txt"
echo "stress 1,000,000 with impostors after against before:" | tee -a "$res/summary.txt"
"$bin/image-psnr" "$res/stress1m-before.png" "$res/stress1m-after.png" | tee -a "$res/summary.txt"
rm -f "$res"/stress1m-*.png "$res/fig4-before.png"
tar -czf "$out/gbehind.tgz" -C /tmp gbehind
