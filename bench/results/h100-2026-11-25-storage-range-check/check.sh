#!/usr/bin/env bash
# H100: the storage-range checks (f-new, main at 0840ef4) against the build before them (f-main, efa0968).
set -uo pipefail
bin=$(realpath .devbin); res=/tmp/check; out=${OUT:-/tmp/out}; device=NVIDIA
source "$bin/lent_machine.sh"
begin_run check QUIET
failures=0
row() {
  awk -F, -v k="$1" 'NR == 1 { for (i = 1; i <= NF; ++i) c[$i] = i; next }
    { printf "%-22s %8s | frame %7.3f p95 %7.3f | shadow %7.3f draw %6.3f\n", k, $c["characters"], $c["median_frame_ms"], $c["p95_frame_ms"], $c["gpu_shadow_ms"], $c["gpu_draw_ms"] }' "$2" | tee -a "$res/summary.txt"
}
for round in 1 2; do
  for config in fig4 default above1m uhd1m; do
    case $config in
      fig4) extra=(--scene paper-fig4 --size 1920x1080) ;;
      default) extra=(--scene default --size 1920x1080) ;;
      above1m) extra=(--scene stress --counts 1000000 --impostors on --size 1920x1080) ;;
      uhd1m) extra=(--scene stress --counts 1000000 --impostors on --size 3840x2160) ;;
    esac
    for v in main new; do
      key=$config-$v-$round
      run "$key" "$bin/f-$v/crowd-bench" "${device_flag[@]}" "${extra[@]}" --methods compute --frames 200 --warmup 20 --csv "$res/$key.csv"
      row "$key" "$res/$key.csv"
    done
  done
done
"$bin/f-new/crowd-render" "${device_flag[@]}" --list-devices > "$res/devices.txt" 2>&1
tar -czf "$out/check.tgz" -C /tmp check
echo "failures: $failures"
