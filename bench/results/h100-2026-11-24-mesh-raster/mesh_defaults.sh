#!/usr/bin/env bash
# Whether auto should draw small meshes in compute by default: the frames the README reports, with
# --mesh-raster-limit 0 (meshes on the hardware), 64 and 128, compute skinning, 1920x1080, twice interleaved.
set -uo pipefail
bin=$(realpath .devbin); res=/tmp/mesh-defaults; out=${OUT:-/tmp/out}; device=NVIDIA
source "$bin/lent_machine.sh"
begin_run mesh_defaults
failures=0
scenes=("fig4:--scene paper-fig4" "stress100k-in:--scene stress --counts 100000 --start 20"
        "stress1M-above-imp:--scene stress --counts 1000000 --impostors on" "default:--scene default")
for round in 1 2; do
  for s in "${scenes[@]}"; do
    name=${s%%:*}; read -r -a flags <<<"${s#*:}"
    for lim in 0 64 128; do
      run "$name-$lim-$round" "$bin/crowd-bench" "${device_flag[@]}" "${flags[@]}" --methods compute --mesh-raster-limit $lim \
        --frames 200 --warmup 20 --size 1920x1080 --csv "$res/$name-$lim-$round.csv"
    done
  done
done
printf "%-20s %5s %3s | %9s %9s %8s | %8s %8s %8s\n" scene limit r frame p95 fps shadow raster draw
for round in 1 2; do for s in "${scenes[@]}"; do name=${s%%:*}; for lim in 0 64 128; do
  c=$res/$name-$lim-$round.csv
  printf "%-20s %5s %3s | %9.3f %9.3f %8.1f | %8.3f %8.3f %8.3f\n" "$name" "$lim" "$round" "$(csv_value "$c" median_frame_ms)" \
    "$(csv_value "$c" p95_frame_ms)" "$(csv_value "$c" fps)" "$(csv_value "$c" gpu_shadow_ms)" "$(csv_value "$c" gpu_raster_ms)" "$(csv_value "$c" gpu_draw_ms)"
done; done; done | tee "$res/summary.txt"
tar -czf "$out/mesh-defaults.tgz" -C /tmp mesh-defaults
