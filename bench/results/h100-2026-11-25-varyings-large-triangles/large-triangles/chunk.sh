#!/usr/bin/env bash
# H100: main (var-main), packed varyings (var-pack), packed varyings and the shadow raster's large
# triangles shared out (var-chunk). Table 1's sweep (a map fitted to few soldiers: large triangles),
# paper-fig4, stress 100,000 inside, the default scene, 1,000,000 with impostors inside.
set -uo pipefail
bin=$(realpath .devbin); res=/tmp/chunk; out=${OUT:-/tmp/out}; device=NVIDIA
source "$bin/lent_machine.sh"
begin_run chunk
failures=0
echo "commands: crowd-bench <args> --frames 200 --warmup 20 --size 1920x1080 --csv (var-main, var-pack, var-chunk)" >"$res/summary.txt"
row() {  # KEY CSV: every row of the CSV, one line each
  awk -F, -v k="$1" 'NR == 1 { for (i = 1; i <= NF; ++i) c[$i] = i; next }
    { printf "%-24s %-7s %7s | frame %7.3f p95 %7.3f | shadow %6.3f draw %6.3f\n", k, $c["model"], $c["characters"],
      $c["median_frame_ms"], $c["p95_frame_ms"], $c["gpu_shadow_ms"], $c["gpu_draw_ms"] }' "$2" | tee -a "$res/summary.txt"
}
for round in 1 2; do
  for config in t1 fig4-on fig4-off 100k-on 100k-off default-on inside1m; do
    case $config in
      t1) extra=(--models soldier --counts 1,16,64,256,1024 --methods compute --shadows on) ;;
      fig4-on) extra=(--scene paper-fig4 --methods compute --shadows on) ;;
      fig4-off) extra=(--scene paper-fig4 --methods compute --shadows off) ;;
      100k-on) extra=(--scene stress --counts 100000 --start 20 --methods compute --shadows on) ;;
      100k-off) extra=(--scene stress --counts 100000 --start 20 --methods compute --shadows off) ;;
      default-on) extra=(--scene default --methods compute --shadows on) ;;
      inside1m) extra=(--scene stress --counts 1000000 --impostors on --start 20 --methods compute --shadows on) ;;
    esac
    for v in main pack chunk; do
      key=$config-$v-$round
      run "$key" "$bin/var-$v/crowd-bench" "${device_flag[@]}" "${extra[@]}" --frames 200 --warmup 20 --size 1920x1080 --csv "$res/$key.csv"
      row "$key" "$res/$key.csv"
    done
  done
done
key=t1-chunk-hardware
run "$key" "$bin/var-chunk/crowd-bench" "${device_flag[@]}" --models soldier --counts 1,16,64,256,1024 --methods compute --shadows on --shadow-raster hardware --frames 200 --warmup 20 --size 1920x1080 --csv "$res/$key.csv"
row "$key" "$res/$key.csv"
tar -czf "$out/chunk.tgz" -C /tmp chunk
echo "failures: $failures"
