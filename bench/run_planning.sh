#!/usr/bin/env bash
# Planning a milling crowd, on a lent GPU machine (issue 18: no hitches from planning): crowd-bench on
# stress with COUNT milling soldiers (impostors on, compute, 1920x1080), from above (the first frames
# from 1 s, as a host starting the scene sees them, and from 30 s, every character past its first
# episode) and inside the crowd (--start 20), and the same crowd in place (no planning: the frame's own
# spread on that camera path). Prints median and p95 of the frame and of the CPU's planning
# (Crowd::advanceTo) and p95 over median; writes the JSON of each run to $OUT.
#
# Expects the Vulkan loader packages in .gl/ and crowd-bench and crowd-render in .devbin/ (carried).
#   on the H100:      bash bench/run_planning.sh
#   here on lavapipe: DEVICE= FRAMES=20 WARMUP=2 SIZE=320x180 COUNT=4000 bash bench/run_planning.sh
# FRAMES (default 600) and WARMUP (60) as crowd-bench's --frames and --warmup; DEVICE (NVIDIA): part of
# the device's name, empty for the first device; SIZE (1920x1080); COUNT (1000000).
set -uo pipefail
source "$(dirname "${BASH_SOURCE[0]}")/lent_machine.sh"
frames=${FRAMES:-600}
warmup=${WARMUP:-60}
device=${DEVICE-NVIDIA}
size=${SIZE:-1920x1080}
count=${COUNT:-1000000}
bin=$PWD/.devbin
res=/tmp/planning
out=${OUT:-/tmp/out}
begin_run run_planning

# The first value of "$2" in the JSON file $1 (crowd-bench's report; its CSV has no planning columns).
json_value() { grep -o "\"$2\": *[-0-9.e+]*" "$1" | head -1 | sed 's/.*: *//'; }

failures=0
printf '%-28s %10s %10s %8s %10s %10s\n' run frame_ms p95_ms ratio plan_ms p95_plan
for config in "mill-above:--behaviour mill --start 1" "mill-above-steady:--behaviour mill --start 30" \
              "mill-inside:--behaviour mill --start 20" "in-place-above:--behaviour in-place --start 1" \
              "in-place-inside:--behaviour in-place --start 20"; do
  name=${config%%:*}
  # shellcheck disable=SC2086  # the flags are words
  run "$name" "$bin/crowd-bench" "${device_flag[@]}" --scene stress --counts "$count" ${config#*:} --impostors on \
    --methods compute --size "$size" --frames "$frames" --warmup "$warmup" --json "$out/$name.json" || continue
  median=$(json_value "$out/$name.json" median_frame_ms)
  p95=$(json_value "$out/$name.json" p95_frame_ms)
  printf '%-28s %10.2f %10.2f %8s %10.2f %10.2f\n' "$name" "$median" "$p95" \
    "$(awk -v a="$median" -v b="$p95" 'BEGIN { printf "%.2fx", b / a }')" \
    "$(json_value "$out/$name.json" cpu_plan_ms)" "$(json_value "$out/$name.json" p95_cpu_plan_ms)"
done
cp "$res/commands.txt" "$out/" 2>/dev/null
exit $((failures > 0))
