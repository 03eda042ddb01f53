#!/usr/bin/env bash
# The far crowd's splats of impostors under two pixels: cost against main (.devbin) and pictures
# against the 4x4 supersampled render (var-splat build).
set -uo pipefail
source .devbin/lent_machine.sh
bin=$PWD/.devbin; res=/tmp/splat; out=${OUT:-/tmp/out}; device=NVIDIA
begin_run splat_ab
failures=0
for round in 1 2; do
  for v in "10000000:above" "10000000:inside" "1000000:above" "1000000:inside"; do
    IFS=: read -r n cam <<<"$v"; start=0; [[ $cam == inside ]] && start=20
    for b in main splat; do
      exe=$bin/crowd-bench; [[ $b == splat ]] && exe=$bin/var-splat/crowd-bench
      c="$res/bench-$n-$cam-$b-$round.csv"
      run "$n-$cam-$b-$round" "$exe" "${device_flag[@]}" --scene stress --counts $n --models soldier --start $start --impostors on --mesh-capacity 65536 --shadows on --methods compute --frames 60 --warmup 10 --size 1920x1080 --csv "$c"
      printf "%-8s %-6s %-5s %s | frame %7.3f p95 %7.3f | raster %6.3f draw %6.3f total %6.3f\n" "$n" "$cam" "$b" "$round" "$(csv_value "$c" median_frame_ms)" "$(csv_value "$c" p95_frame_ms)" "$(csv_value "$c" gpu_raster_ms)" "$(csv_value "$c" gpu_draw_ms)" "$(csv_value "$c" gpu_total_ms)" | tee -a "$res/summary.txt"
    done
  done
done
for n in 10000000 1000000; do
scene=(--scene stress --count $n --start 0 --impostors on --method compute --aa off)
for f in 5 30; do
  [[ $n == 10000000 && $f == 30 ]] && continue
  run "ref-$n-$f" "$bin/var-splat/crowd-render" "${device_flag[@]}" "${scene[@]}" --far-crowd off --frames $f --size 7680x4320 --out "$res/big-$n-$f.png"
  "$bin/image-downsample" "$res/big-$n-$f.png" 4 "$res/ref-$n-$f.png" >/dev/null; rm -f "$res/big-$n-$f.png"
  for b in main splat; do
    exe=$bin/crowd-render; [[ $b == splat ]] && exe=$bin/var-splat/crowd-render
    run "pic-$n-$f-$b" "$exe" "${device_flag[@]}" "${scene[@]}" --frames $f --size 1920x1080 --out "$res/$b-$n-$f.png"
    printf "$n frame %2s %-5s: " $f $b | tee -a "$res/summary.txt"; "$bin/image-psnr" "$res/ref-$n-$f.png" "$res/$b-$n-$f.png" | tee -a "$res/summary.txt"; echo | tee -a "$res/summary.txt"
  done
  printf "$n frame %2s main vs splat: " $f | tee -a "$res/summary.txt"; "$bin/image-psnr" "$res/main-$n-$f.png" "$res/splat-$n-$f.png" | tee -a "$res/summary.txt"; echo | tee -a "$res/summary.txt"
done
done
mkdir -p "$out/pics"; cp $res/*-10000000-5.png "$out/pics/" 2>/dev/null
rm -f $res/*.png; tar -czf "$out/splat.tgz" -C /tmp splat
