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
tar -czf "$out/whole2.tgz" -C /tmp whole
