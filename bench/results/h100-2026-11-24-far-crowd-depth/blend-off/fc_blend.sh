#!/usr/bin/env bash
# Far crowd (optical depth): frames 5/30/60 with --impostor-blend off: average, off vs 4x4 supersampled (blend off too).
set -uo pipefail
source .devbin/lent_machine.sh
bin=$PWD/.devbin; res=/tmp/fcb; out=${OUT:-/tmp/out}; device=NVIDIA
begin_run fc_blend
failures=0
for fr in 5 30 60; do
  B=(--scene stress --count 1000000 --impostors on --method compute --aa off --start 0 --frames $fr --impostor-blend off)
  for s in average off; do run "$s-$fr" "$bin/crowd-render" "${device_flag[@]}" "${B[@]}" --far-crowd $s --size 1920x1080 --out "$res/$s-$fr.png"; done
  run "ss4-$fr" "$bin/crowd-render" "${device_flag[@]}" "${B[@]}" --far-crowd off --size 7680x4320 --out "$res/ss4-$fr.png"
  "$bin/image-downsample" "$res/ss4-$fr.png" 4 "$res/ss-$fr.png"; rm -f "$res/ss4-$fr.png"
  for s in average off; do echo "blend off, frame $fr $s: $("$bin/image-psnr" "$res/$s-$fr.png" "$res/ss-$fr.png")" | tee -a "$res/summary.txt"; done
done
for f in $res/*.png; do "$bin/image-downsample" "$f" 2 "${f%.png}-half.png"; rm -f "$f"; done
tar -czf "$out/fcb.tgz" -C /tmp fcb
