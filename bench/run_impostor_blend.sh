#!/usr/bin/env bash
# Issue 19's impostor blend measured on a lent GPU machine: crowd-bench on stress 1,000,000 from above
# with impostors (every soldier an impostor; the impostor draw is the frame), compute, 1920x1080, for
# each build given, interleaved, twice, so drift shows. Prints the GPU total, the draw pass (the colour
# pass, where impostors are drawn) and the shadow pass (impostor shadows) per build and round, and the
# change against the first build of the same round; writes $OUT/impostor-blend.tgz (outputs and CSVs).
#
# Builds: BINS (".devbin"), folders each holding crowd-bench with its shared libraries, the first the
# baseline. To time the blend against the nearest cell, carry a build of the commit before the blend
# (bfd7066^) as .devbin-nearest and give BINS=".devbin-nearest .devbin".
# Expects the Vulkan loader packages in .gl/ (carried).
#   on the H100:      BINS=".devbin-nearest .devbin" bash bench/run_impostor_blend.sh
#   here on lavapipe: DEVICE= COUNT=20000 SIZE=960x540 FRAMES=4 WARMUP=1 bash bench/run_impostor_blend.sh
# FRAMES (default 300) and WARMUP (30): crowd-bench's --frames and --warmup; COUNT (1000000); SIZE
# (1920x1080); DEVICE (NVIDIA): part of the device's name, empty for the first device.
set -uo pipefail
source "$(dirname "${BASH_SOURCE[0]}")/lent_machine.sh"
frames=${FRAMES:-300}
warmup=${WARMUP:-30}
count=${COUNT:-1000000}
size=${SIZE:-1920x1080}
device=${DEVICE-NVIDIA}
read -r -a bins <<<"${BINS:-.devbin}"
res=/tmp/impostor-blend
out=${OUT:-/tmp/out}
rm -rf "$res"
mkdir -p "$res" "$out"
install_vulkan_loader
device_flag=()
[[ -n $device ]] && device_flag=(--device "$device")
first=$PWD/${bins[0]}
probe() { LD_LIBRARY_PATH=$first "$first/crowd-bench" "${device_flag[@]}" --counts 1 --frames 1 --warmup 0 --size 64x64 >"$res/probe.txt" 2>&1; }
find_device run_impostor_blend quiet
failures=0
for round in 1 2; do
  for b in "${!bins[@]}"; do
    bin=$PWD/${bins[$b]}
    cmd=("$bin/crowd-bench" "${device_flag[@]}" --scene stress --counts "$count" --impostors on --methods compute
         --size "$size" --frames "$frames" --warmup "$warmup" --csv "$res/bench-$b-$round.csv")
    echo "${cmd[*]}" >>"$res/commands.txt"
    echo "== ${bins[$b]}, round $round"
    LD_LIBRARY_PATH=$bin "${cmd[@]}" >"$res/bench-$b-$round.txt" 2>&1 || {
      failures=$((failures + 1)); echo "   failed:"; tail -3 "$res/bench-$b-$round.txt"; }
  done
done

# The value of column $2 in the first data row of the CSV file $1 (no quoted commas in these columns).
csv_value() {
  awk -F, -v want="$2" 'NR == 1 { for (i = 1; i <= NF; i++) if ($i == want) c = i; next } NR == 2 { if (c) print $c; exit }' "$1" 2>/dev/null
}
percent() { awk -v a="$1" -v b="$2" 'BEGIN { if (a + 0 > 0 && b != "") printf "%+.1f%%", 100 * (b - a) / a; else print "-" }'; }
{
  echo "stress $count from above, --impostors on, compute, $size; crowd-bench medians over $frames frames after"
  echo "$warmup warm-up, ms (gpu: GPU total, draw: the colour pass, shadow: the shadow pass, frame: wall clock);"
  echo "+%: against ${bins[0]} in the same round"
  printf "%-18s %1s | %8s %7s | %8s %7s | %8s %7s | %8s\n" build r gpu "+%" draw "+%" shadow "+%" frame
  for round in 1 2; do
    base=$res/bench-0-$round.csv
    for b in "${!bins[@]}"; do
      csv=$res/bench-$b-$round.csv
      printf "%-18s %1s | %8s %7s | %8s %7s | %8s %7s | %8s\n" "${bins[$b]}" "$round" \
        "$(csv_value "$csv" gpu_total_ms)" "$(percent "$(csv_value "$base" gpu_total_ms)" "$(csv_value "$csv" gpu_total_ms)")" \
        "$(csv_value "$csv" gpu_draw_ms)" "$(percent "$(csv_value "$base" gpu_draw_ms)" "$(csv_value "$csv" gpu_draw_ms)")" \
        "$(csv_value "$csv" gpu_shadow_ms)" "$(percent "$(csv_value "$base" gpu_shadow_ms)" "$(csv_value "$csv" gpu_shadow_ms)")" \
        "$(csv_value "$csv" median_frame_ms)"
    done
  done
} | tee "$res/table.txt"
tar -czf "$out/impostor-blend.tgz" -C /tmp impostor-blend
exit $((failures > 0))
