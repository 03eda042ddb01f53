#!/usr/bin/env bash
# Ground drawn after the opaque characters (X_LATE=1) against before them, on the H100.
set -uo pipefail
source .devbin/lent_machine.sh
bin=$PWD/.devbin; res=/tmp/glate; out=${OUT:-/tmp/out}; device=NVIDIA
begin_run ground_late QUIET
failures=0
for round in 1 2; do
  for scene in paper-fig4 default stress100k stress1m; do
    extra=(--scene $scene)
    [[ $scene == stress100k ]] && extra=(--scene stress --counts 100000 --start 20)
    [[ $scene == stress1m ]] && extra=(--scene stress --counts 1000000 --impostors on)
    for g in first late; do
      if [[ $g == late ]]; then export X_LATE=1; else unset X_LATE; fi
      run "$scene-$g-$round" "$bin/var-exp/crowd-bench" "${device_flag[@]}" "${extra[@]}" --methods compute --frames 150 --warmup 20 --size 1920x1080 --csv "$res/$scene-$g-$round.csv"
      printf "%-10s %-5s %s | frame %8.3f p95 %8.3f shadow %6.3f draw %6.3f\n" "$scene" "$g" "$round" "$(csv_value "$res/$scene-$g-$round.csv" median_frame_ms)" "$(csv_value "$res/$scene-$g-$round.csv" p95_frame_ms)" "$(csv_value "$res/$scene-$g-$round.csv" gpu_shadow_ms)" "$(csv_value "$res/$scene-$g-$round.csv" gpu_draw_ms)" | tee -a "$res/summary.txt"
    done
  done
done
unset X_LATE
tar -czf "$out/glate.tgz" -C /tmp glate
