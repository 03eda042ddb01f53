#!/usr/bin/env bash
# H100: paper-fig4's colour pass against its triangles and draws: every character at one level, props on/off.
set -uo pipefail
bin=$(realpath .devbin); res=/tmp/draws; out=${OUT:-/tmp/out}; device=NVIDIA
source "$bin/lent_machine.sh"
begin_run draws QUIET
failures=0
row() {
  awk -F, -v k="$1" 'NR == 1 { for (i = 1; i <= NF; ++i) c[$i] = i; next }
    { printf "%-22s %8s | frame %7.3f p95 %7.3f | shadow %7.3f draw %6.3f\n", k, $c["characters"], $c["median_frame_ms"], $c["p95_frame_ms"], $c["gpu_shadow_ms"], $c["gpu_draw_ms"] }' "$2" | tee -a "$res/summary.txt"
}
for round in 1 2; do
  for config in def lod0 lod2 def-np lod0-np lod2-np; do
    case $config in
      def) extra=() ;;
      lod0) extra=(--lod-thresholds 0.002,0.001) ;;
      lod2) extra=(--lod-thresholds 100000,50000) ;;
      def-np) extra=(--props off) ;;
      lod0-np) extra=(--lod-thresholds 0.002,0.001 --props off) ;;
      lod2-np) extra=(--lod-thresholds 100000,50000 --props off) ;;
    esac
    key=$config-$round
    run "$key" "$bin/f-main/crowd-bench" "${device_flag[@]}" --scene paper-fig4 "${extra[@]}" --shadows off --lod-fade off --methods compute --frames 200 --warmup 20 --size 1920x1080 --csv "$res/$key.csv"
    row "$key" "$res/$key.csv"
  done
done
for config in def lod0 lod2 def-np lod2-np; do
  case $config in
    def) extra=() ;; lod0) extra=(--lod-thresholds 0.002,0.001) ;; lod2) extra=(--lod-thresholds 100000,50000) ;;
    def-np) extra=(--props off) ;; lod2-np) extra=(--lod-thresholds 100000,50000 --props off) ;;
  esac
  "$bin/f-main/crowd-render" "${device_flag[@]}" --scene paper-fig4 "${extra[@]}" --shadows off --lod-fade off --method compute --frames 30 --size 1920x1080 --json "$res/$config.json" --out "$res/$config.png" >"$res/render-$config.txt" 2>&1
  python3 -c "import json;j=json.load(open('$res/$config.json'));print('$config', j['median_visible_per_lod'], j['median_triangles'])" 2>/dev/null || grep -A4 median_visible_per_lod "$res/$config.json" | tr -d '\n '; echo
done
tar -czf "$out/draws.tgz" -C /tmp draws
echo "failures: $failures"
