#!/usr/bin/env bash
# H100: impostor casters shared among workgroups when they are fewer than the workgroups (var-imp)
# against one workgroup a caster (var-chunk, main before it). Few casters with a map fitted to them
# (every character an impostor, and small groups seen from high above with default thresholds), and
# large crowds for regressions.
set -uo pipefail
bin=$(realpath .devbin); res=/tmp/impfew2; out=${OUT:-/tmp/out}; device=NVIDIA
source "$bin/lent_machine.sh"
begin_run impfew2 QUIET
failures=0
row() {
  awk -F, -v k="$1" 'NR == 1 { for (i = 1; i <= NF; ++i) c[$i] = i; next }
    { printf "%-22s %8s | frame %7.3f p95 %7.3f | shadow %7.3f draw %6.3f | impostors %s\n", k, $c["characters"], $c["median_frame_ms"], $c["p95_frame_ms"], $c["gpu_shadow_ms"], $c["gpu_draw_ms"], $c["impostors"] }' "$2" | tee -a "$res/summary.txt"
}
for round in 1 2; do
  for config in forced above inside1m above1m fig4; do
    case $config in
      forced) extra=(--scene stress --counts 1,16,64,256,1024,16384 --impostors on --impostor-threshold 100000 --lod-thresholds 300000,200000) ;;
      above) extra=(--scene stress --counts 16,64,256 --impostors on --start 0) ;;
      inside1m) extra=(--scene stress --counts 1000000 --impostors on --start 20) ;;
      above1m) extra=(--scene stress --counts 1000000 --impostors on) ;;
      fig4) extra=(--scene paper-fig4) ;;
    esac
    for v in chunk imp; do
      key=$config-$v-$round
      run "$key" "$bin/var-$v/crowd-bench" "${device_flag[@]}" "${extra[@]}" --methods compute --frames 100 --warmup 10 --size 1920x1080 --csv "$res/$key.csv"
      row "$key" "$res/$key.csv"
    done
  done
done
tar -czf "$out/impfew2.tgz" -C /tmp impfew2
echo "failures: $failures"
