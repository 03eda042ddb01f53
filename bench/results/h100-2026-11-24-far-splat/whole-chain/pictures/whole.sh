#!/usr/bin/env bash
# Splat threshold 2 px (.devbin, main at 384b29a) against 4 px (.devbin/var-whole): cost, and pictures
# against the 4x4 impostor render and the 4x4 mesh render.
set -uo pipefail
source .devbin/lent_machine.sh
bin=$PWD/.devbin; res=/tmp/whole; out=${OUT:-/tmp/out}; device=NVIDIA
begin_run whole
failures=0
exe() { [[ $1 == before ]] && echo "$bin/$2" || echo "$bin/var-whole/$2"; }
for round in 1 2; do
  for v in "10000000:above" "10000000:inside" "1000000:above" "1000000:inside"; do
    IFS=: read -r n cam <<<"$v"; start=0; [[ $cam == inside ]] && start=20
    for b in before whole; do
      c="$res/bench-$n-$cam-$b-$round.csv"
      run "$n-$cam-$b-$round" "$(exe $b crowd-bench)" "${device_flag[@]}" --scene stress --counts $n --models soldier --start $start --impostors on --mesh-capacity 65536 --shadows on --methods compute --frames 60 --warmup 10 --size 1920x1080 --csv "$c"
      printf "%-8s %-6s %-4s %s | frame %7.3f p95 %7.3f | raster %6.3f draw %6.3f total %6.3f\n" "$n" "$cam" "$b" "$round" "$(csv_value "$c" median_frame_ms)" "$(csv_value "$c" p95_frame_ms)" "$(csv_value "$c" gpu_raster_ms)" "$(csv_value "$c" gpu_draw_ms)" "$(csv_value "$c" gpu_total_ms)" | tee -a "$res/summary.txt"
    done
  done
done
# 1,000,000 from above at 1920x1080 against the 4x4 impostor render (--far-crowd off);
# 250,000 from above at 960x540 against the 4x4 impostor render and the 4x4 mesh render (--impostors off).
for spec in "1000000:1920x1080:7680x4320:5" "1000000:1920x1080:7680x4320:30" "250000:960x540:3840x2160:5" "250000:960x540:3840x2160:30"; do
  IFS=: read -r n size big f <<<"$spec"
  B=(--scene stress --count $n --method compute --aa off --start 0 --frames $f)
  run "imp4-$n-$f" "$bin/var-whole/crowd-render" "${device_flag[@]}" "${B[@]}" --impostors on --far-crowd off --size $big --out "$res/big.png" && "$bin/image-downsample" "$res/big.png" 4 "$res/imp-$n-$f.png"; rm -f "$res/big.png"
  refs=(imp)
  if [[ $n == 250000 ]]; then
    run "mesh4-$n-$f" "$bin/var-whole/crowd-render" "${device_flag[@]}" "${B[@]}" --impostors off --size $big --out "$res/big.png" && "$bin/image-downsample" "$res/big.png" 4 "$res/mesh-$n-$f.png"; rm -f "$res/big.png"
    refs=(imp mesh)
  fi
  for b in before whole off; do
    if [[ $b == off ]]; then run "pic-$n-$f-$b" "$(exe whole crowd-render)" "${device_flag[@]}" "${B[@]}" --impostors on --far-crowd off --size $size --out "$res/$b-$n-$f.png"
    else run "pic-$n-$f-$b" "$(exe $b crowd-render)" "${device_flag[@]}" "${B[@]}" --impostors on --size $size --out "$res/$b-$n-$f.png"; fi
    for r in "${refs[@]}"; do echo "$n frame $f $b vs $r: $("$bin/image-psnr" "$res/$r-$n-$f.png" "$res/$b-$n-$f.png")" | tee -a "$res/summary.txt"; done
  done
done
mkdir -p "$out/pics"; for f in before whole imp; do "$bin/image-downsample" "$res/$f-1000000-5.png" 1 "$out/pics/$f-1000000-5.png" 2>/dev/null || cp "$res/$f-1000000-5.png" "$out/pics/"; done
rm -f $res/*.png; tar -czf "$out/whole.tgz" -C /tmp whole
