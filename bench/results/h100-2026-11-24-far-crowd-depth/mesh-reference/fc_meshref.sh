#!/usr/bin/env bash
# Far crowd against a mesh reference: stress 250k from above, 3840x2160 with --impostors off (every soldier a mesh), box-filtered to 1920x1080.
set -uo pipefail
source .devbin/lent_machine.sh
bin=$PWD/.devbin; res=/tmp/fcm; out=${OUT:-/tmp/out}; device=NVIDIA
begin_run fc_meshref
failures=0
for fr in 5 30 60; do
  B=(--scene stress --count 250000 --method compute --aa off --start 0 --frames $fr)
  for s in average off; do run "$s-$fr" "$bin/crowd-render" "${device_flag[@]}" "${B[@]}" --impostors on --far-crowd $s --size 960x540 --out "$res/$s-$fr.png"; done
  run "mesh4-$fr" "$bin/crowd-render" "${device_flag[@]}" "${B[@]}" --impostors off --size 3840x2160 --out "$res/mesh4-$fr.png" && "$bin/image-downsample" "$res/mesh4-$fr.png" 4 "$res/mesh-$fr.png"; rm -f "$res/mesh4-$fr.png"
  run "ss4-$fr" "$bin/crowd-render" "${device_flag[@]}" "${B[@]}" --impostors on --far-crowd off --size 3840x2160 --out "$res/ss4-$fr.png" && "$bin/image-downsample" "$res/ss4-$fr.png" 4 "$res/ss-$fr.png"; rm -f "$res/ss4-$fr.png"
  for s in average off ss; do echo "frame $fr $s vs mesh reference: $("$bin/image-psnr" "$res/$s-$fr.png" "$res/mesh-$fr.png")" | tee -a "$res/summary.txt"; done
done
tail -3 $res/mesh4-30.txt
for f in $res/*.png; do "$bin/image-downsample" "$f" 2 "${f%.png}-half.png"; rm -f "$f"; done
tar -czf "$out/fcm.tgz" -C /tmp fcm
