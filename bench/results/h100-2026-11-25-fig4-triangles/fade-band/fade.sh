#!/usr/bin/env bash
# H100: what paper-fig4's fades cost as their band narrows (--lod-hysteresis), against no fades.
set -uo pipefail
bin=$(realpath .devbin); res=/tmp/fade; out=${OUT:-/tmp/out}; device=NVIDIA
source "$bin/lent_machine.sh"
begin_run fade QUIET
failures=0
row() {
  awk -F, -v k="$1" 'NR == 1 { for (i = 1; i <= NF; ++i) c[$i] = i; next }
    { printf "%-22s %8s | frame %7.3f p95 %7.3f | shadow %7.3f draw %6.3f\n", k, $c["characters"], $c["median_frame_ms"], $c["p95_frame_ms"], $c["gpu_shadow_ms"], $c["gpu_draw_ms"] }' "$2" | tee -a "$res/summary.txt"
}
for round in 1 2; do
  for config in h10 h05 h025 h0 nofade off; do
    case $config in
      h10) extra=(--lod-hysteresis 0.1) ;;
      h05) extra=(--lod-hysteresis 0.05) ;;
      h025) extra=(--lod-hysteresis 0.025) ;;
      h0) extra=(--lod-hysteresis 0) ;;
      nofade) extra=(--lod-fade off) ;;
      off) extra=(--shadows off) ;;
    esac
    key=$config-$round
    run "$key" "$bin/f-main/crowd-bench" "${device_flag[@]}" --scene paper-fig4 "${extra[@]}" --methods compute --frames 200 --warmup 20 --size 1920x1080 --csv "$res/$key.csv"
    row "$key" "$res/$key.csv"
  done
done
for h in 0.1 0.05 0.025; do
  "$bin/f-main/crowd-render" "${device_flag[@]}" --scene paper-fig4 --method compute --lod-hysteresis $h --frames 60 --size 1920x1080 --json "$res/fig4-$h.json" --out "$res/fig4-$h.png" >"$res/render-$h.txt" 2>&1
  grep -o '"median_visible_per_lod": \[[^]]*\]' "$res/fig4-$h.json" | tr -d '\n '; echo " h=$h"
done
tar -czf "$out/fade.tgz" -C /tmp fade
echo "failures: $failures"
