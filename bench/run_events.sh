#!/usr/bin/env bash
# The GPU event pass (issue 20's target: events of 100,000 visible characters in <= 0.1 ms), on a lent
# GPU machine: crowd-bench, method compute, stress scene of walking soldiers seen from above at t = 0
# (every one in view), --events on and off, twice, interleaved. Prints the median GPU time of the
# "events" pass (timestamp queries around it, as every pass), the characters in view, and the frame
# with and without events; writes $OUT/events.tgz (every run's output and JSON).
#
# The pass finds events only in clips that carry them: the built-in soldier's walk has footsteps once
# the footsteps branch is merged; before that the figure is the pass's cost with nothing to fire
# (one thread per character reading its cull word).
#
# Expects the Vulkan loader packages in .gl/ and crowd-bench in .devbin/ (carried).
#   on the H100:      bash bench/run_events.sh
#   here on lavapipe: DEVICE= FRAMES=3 WARMUP=1 SIZE=320x180 COUNT=2000 bash bench/run_events.sh
# FRAMES (default 300) and WARMUP (30) as crowd-bench's --frames and --warmup; DEVICE (NVIDIA): part of
# the device's name, empty for the first device; SIZE (1920x1080); COUNT (100000).
set -uo pipefail
source "$(dirname "${BASH_SOURCE[0]}")/lent_machine.sh"
frames=${FRAMES:-300}
warmup=${WARMUP:-30}
device=${DEVICE-NVIDIA}
size=${SIZE:-1920x1080}
count=${COUNT:-100000}
bin=$PWD/.devbin
res=/tmp/events
out=${OUT:-/tmp/out}
probe() { "$bin/crowd-bench" "${device_flag[@]}" --counts 1 --frames 1 --warmup 0 --size 64x64 >"$res/probe.txt" 2>&1; }
begin_run run_events

failures=0

# The number after "KEY": in a JSON file (crowd-bench's, one result); empty when absent.
json_number() { grep -o "\"$2\": *[-0-9.e+]*" "$1" | head -1 | sed 's/.*: *//'; }
# The sum of the three numbers of the array "KEY": [a, b, c] (pretty-printed over several lines).
json_sum3() { tr -d ' \n' <"$1" | grep -o "\"$2\":\[[-0-9.e+]*,[-0-9.e+]*,[-0-9.e+]*\]" | head -1 |
  sed 's/.*\[//; s/\]//' | awk -F, '{ printf "%.0f", $1 + $2 + $3 }'; }

for round in 1 2; do
  for events in on off; do
    key=$events-$round
    run "bench-$key" "$bin/crowd-bench" "${device_flag[@]}" --scene stress --counts "$count" --start 0 --clip walk \
      --events "$events" --methods compute --frames "$frames" --warmup "$warmup" --size "$size" --json "$res/bench-$key.json"
  done
done

{
  echo
  echo "compute, $size, stress $count walking soldiers from above (t = 0); crowd-bench medians over $frames frames"
  echo "after $warmup warm-up, ms. events: the event pass's GPU time; frame: wall clock between frame starts."
  printf "%-6s %1s | %10s %10s | %10s %10s\n" events r "in view" "events ms" "frame ms" "gpu ms"
  for round in 1 2; do
    for events in on off; do
      json=$res/bench-$events-$round.json
      if [[ ! -s $json || $(grep -c '"status": "ok"' "$json") == 0 ]]; then
        printf "%-6s %1s | %10s\n" "$events" "$round" skipped
        continue
      fi
      pass=$(json_number "$json" events)
      [[ -n $pass ]] && pass=$(printf "%.4f" "$pass")
      printf "%-6s %1s | %10s %10s | %10.3f %10.3f\n" "$events" "$round" "$(json_sum3 "$json" median_visible_per_lod)" \
        "${pass:--}" "$(json_number "$json" median_frame_ms)" "$(json_number "$json" gpu_total_ms)"
    done
  done
} | tee "$res/summary.txt"
tar -czf "$out/events.tgz" -C /tmp events
[[ $failures == 0 ]] || { echo "run_events: $failures run(s) failed (see their .txt in events.tgz)"; exit 1; }
