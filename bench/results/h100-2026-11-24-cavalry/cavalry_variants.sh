#!/usr/bin/env bash
# The cavalry scene at 13,334 characters (about 10,000 riders): the default frame, small meshes in
# compute (--mesh-raster-limit 64), impostors on, and both; compute skinning, 1920x1080, twice interleaved.
set -uo pipefail
bin=$(realpath .devbin); res=/tmp/cavalry-variants; out=${OUT:-/tmp/out}; device=NVIDIA
source "$bin/lent_machine.sh"
begin_run cavalry_variants
failures=0
variants=("default:" "mesh-raster-64:--mesh-raster-limit 64" "impostors:--impostors on" "impostors+mesh-raster-64:--impostors on --mesh-raster-limit 64")
for round in 1 2; do for v in "${variants[@]}"; do
  name=${v%%:*}; read -r -a flags <<<"${v#*:}"
  run "$name-$round" "$bin/crowd-bench" "${device_flag[@]}" --scene cavalry --counts 13334 --methods compute "${flags[@]}" \
    --frames 300 --warmup 30 --size 1920x1080 --csv "$res/$name-$round.csv"
done; done
printf "%-26s %2s | %9s %9s %8s | %8s %8s %8s | %9s %9s\n" variant r frame p95 fps shadow raster draw impostors triangles
for round in 1 2; do for v in "${variants[@]}"; do name=${v%%:*}; c=$res/$name-$round.csv
  printf "%-26s %2s | %9.3f %9.3f %8.1f | %8.3f %8.3f %8.3f | %9s %9s\n" "$name" "$round" "$(csv_value "$c" median_frame_ms)" \
    "$(csv_value "$c" p95_frame_ms)" "$(csv_value "$c" fps)" "$(csv_value "$c" gpu_shadow_ms)" "$(csv_value "$c" gpu_raster_ms)" \
    "$(csv_value "$c" gpu_draw_ms)" "$(csv_value "$c" impostors)" "$(csv_value "$c" triangles_drawn)"
done; done | tee "$res/summary.txt"
tar -czf "$out/cavalry-variants.tgz" -C /tmp cavalry-variants
