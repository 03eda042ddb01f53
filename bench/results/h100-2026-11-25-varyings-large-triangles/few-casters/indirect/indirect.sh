#!/usr/bin/env bash
# H100: the large triangles' second dispatch sized by what was listed (vkCmdDispatchIndirect, var-ind)
# against a fixed 1,024 workgroups (var-rec2).
set -uo pipefail
bin=$(realpath .devbin); res=/tmp/indirect; out=${OUT:-/tmp/out}; device=NVIDIA
source "$bin/lent_machine.sh"
begin_run indirect QUIET
failures=0
row() {
  awk -F, -v k="$1" 'NR == 1 { for (i = 1; i <= NF; ++i) c[$i] = i; next }
    { printf "%-22s %8s | frame %7.3f p95 %7.3f | shadow %7.3f draw %6.3f\n", k, $c["characters"], $c["median_frame_ms"], $c["p95_frame_ms"], $c["gpu_shadow_ms"], $c["gpu_draw_ms"] }' "$2" | tee -a "$res/summary.txt"
}
for round in 1 2; do
  for config in t1 above fig4 100k default inside1m; do
    case $config in
      t1) extra=(--models soldier --counts 1,16,64,256,1024) ;;
      above) extra=(--scene stress --counts 1,16,64,256,1024 --impostors on --start 0) ;;
      forced) extra=(--scene stress --counts 1,16,64,256 --impostors on --impostor-threshold 100000 --lod-thresholds 300000,200000) ;;
      fig4) extra=(--scene paper-fig4) ;;
      100k) extra=(--scene stress --counts 100000 --start 20) ;;
      default) extra=(--scene default) ;;
      inside1m) extra=(--scene stress --counts 1000000 --impostors on --start 20) ;;
    esac
    for v in rec2 ind; do
      key=$config-$v-$round
      run "$key" "$bin/var-$v/crowd-bench" "${device_flag[@]}" "${extra[@]}" --methods compute --frames 100 --warmup 10 --size 1920x1080 --csv "$res/$key.csv"
      row "$key" "$res/$key.csv"
    done
  done
done
for config in; do
  case $config in
    t1) extra=(--models soldier --counts 1,16,64,256,1024) ;;
    above) extra=(--scene stress --counts 1,16,64,256,1024 --impostors on --start 0) ;;
  esac
  key=$config-rec-hardware
  run "$key" "$bin/var-rec/crowd-bench" "${device_flag[@]}" "${extra[@]}" --shadow-raster hardware --methods compute --frames 100 --warmup 10 --size 1920x1080 --csv "$res/$key.csv"
  row "$key" "$res/$key.csv"
done
tar -czf "$out/indirect.tgz" -C /tmp indirect
echo "failures: $failures"
