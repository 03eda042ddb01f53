#!/usr/bin/env bash
# auto's automatic mesh path (--mesh-raster-limit auto, the default) against meshes on the hardware
# (--mesh-raster-limit 0) on the frames the README reports and the heavy all-mesh ones; compute skinning,
# 1920x1080, 200 frames after 20, two rounds interleaved.
set -uo pipefail
bin=$(realpath .devbin); res=/tmp/mesh-auto; out=${OUT:-/tmp/out}; device=NVIDIA
source "$bin/lent_machine.sh"
begin_run mesh_auto
failures=0
scenes=("fig4:--scene paper-fig4" "default:--scene default" "stress100k-in:--scene stress --counts 100000 --start 20"
        "stress1M-above-imp:--scene stress --counts 1000000 --impostors on"
        "stress250k-in-mesh:--scene stress --counts 250000 --start 20 --impostors off" "cavalry13334:--scene cavalry --counts 13334")
for round in 1 2; do for s in "${scenes[@]}"; do
  name=${s%%:*}; read -r -a flags <<<"${s#*:}"
  for lim in auto 0; do
    run "$name-$lim-$round" "$bin/crowd-bench" "${device_flag[@]}" "${flags[@]}" --methods compute --mesh-raster-limit $lim \
      --frames 200 --warmup 20 --size 1920x1080 --csv "$res/$name-$lim-$round.csv"
  done
done; done
printf "%-20s %5s %2s | %9s %9s %8s | %8s %8s | %10s\n" scene limit r frame p95 fps raster draw triangles
for round in 1 2; do for s in "${scenes[@]}"; do name=${s%%:*}; for lim in auto 0; do
  c=$res/$name-$lim-$round.csv
  printf "%-20s %5s %2s | %9.3f %9.3f %8.1f | %8.3f %8.3f | %10s\n" "$name" "$lim" "$round" "$(csv_value "$c" median_frame_ms)" \
    "$(csv_value "$c" p95_frame_ms)" "$(csv_value "$c" fps)" "$(csv_value "$c" gpu_raster_ms)" "$(csv_value "$c" gpu_draw_ms)" \
    "$(csv_value "$c" triangles_drawn)"
done; done; done | tee "$res/summary.txt"
tar -czf "$out/mesh-auto.tgz" -C /tmp mesh-auto
