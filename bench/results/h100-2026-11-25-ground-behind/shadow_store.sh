#!/usr/bin/env bash
# The compute raster's depth stored into the map's float image (var-store) against copied into the depth
# image (var-new: main with the ground behind), H100; shadows on and off; pictures.
set -uo pipefail
source .devbin/lent_machine.sh
bin=$PWD/.devbin; res=/tmp/sstore; out=${OUT:-/tmp/out}; device=NVIDIA
begin_run shadow_store
failures=0
for round in 1 2; do
  for scene in paper-fig4 stress100k default stress1m; do
    extra=(--scene $scene)
    [[ $scene == stress100k ]] && extra=(--scene stress --counts 100000 --start 20)
    [[ $scene == stress1m ]] && extra=(--scene stress --counts 1000000 --impostors on)
    for sh in on off; do
      [[ $sh == off && $scene == stress1m ]] && continue
      for v in copy store; do
        [[ $sh == off && $v == copy ]] && continue  # shadows off: both builds draw the same frame
        b=$bin/var-new; [[ $v == store ]] && b=$bin/var-store
        name=$scene-$sh-$v-$round
        run "$name" "$b/crowd-bench" "${device_flag[@]}" "${extra[@]}" --shadows $sh --methods compute --frames 200 --warmup 20 --size 1920x1080 --csv "$res/$name.csv"
        printf "%-10s shadows %-3s %-5s %s | frame %8.3f p95 %8.3f shadow %6.3f draw %6.3f\n" "$scene" "$sh" "$v" "$round" "$(csv_value "$res/$name.csv" median_frame_ms)" "$(csv_value "$res/$name.csv" p95_frame_ms)" "$(csv_value "$res/$name.csv" gpu_shadow_ms)" "$(csv_value "$res/$name.csv" gpu_draw_ms)" | tee -a "$res/summary.txt"
      done
    done
  done
done
for v in copy store; do
  b=$bin/var-new; [[ $v == store ]] && b=$bin/var-store
  run "pic-$v" "$b/crowd-render" "${device_flag[@]}" --scene paper-fig4 --method compute --frames 30 --size 1920x1080 --out "$res/fig4-$v.png"
  run "picd-$v" "$b/crowd-render" "${device_flag[@]}" --scene default --method compute --frames 30 --size 1920x1080 --out "$res/default-$v.png"
done
echo "paper-fig4 store against copy:" | tee -a "$res/summary.txt"
"$bin/image-psnr" "$res/fig4-copy.png" "$res/fig4-store.png" | tee -a "$res/summary.txt"
echo "default store against copy:" | tee -a "$res/summary.txt"
"$bin/image-psnr" "$res/default-copy.png" "$res/default-store.png" | tee -a "$res/summary.txt"
rm -f "$res"/*-copy.png "$res/default-store.png"
tar -czf "$out/sstore.tgz" -C /tmp sstore
