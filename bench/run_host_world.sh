#!/usr/bin/env bash
# Issue 40 on a lent GPU machine: the host's world. crowd-bench at 1920x1080, compute, shadows and
# impostors on, medians and p95 over FRAMES after WARMUP, in three parts (PARTS, default "live driven big"):
#   live:   a live population: 1,000,000 soldiers standing (stress) and milling (mill), unchanged and with
#           1 % of them removed and as many spawned every frame (--churn 1); the CPU's share (the library's
#           calls: cpu_ingest_ms) and the frame against the same crowd unchanged;
#   driven: 1,000,000 characters driven by the host, a new sample each every frame, through host arrays
#           (--agents host: Crowd::drive) and through a device buffer (--agents device), against the same
#           crowd milling; a replay of the Juelich corridor recording, COPIES copies side by side; and the
#           stress crowd on hills (--terrain hills) against it flat;
#   big:    10,000,000 soldiers driven through the device buffer from above (t = 0 s) and inside
#           (--start 20), against the same crowd in place.
# Prints one table and writes $OUT/host-world.tgz (every run's output, CSV and JSON).
#
# Expects the Vulkan loader packages in .gl/, crowd-bench (and its shared libraries) in .devbin/ and the
# corridor recording at $TRAJECTORIES (default .devdata/juelich-bidirectional-corridor.txt; the replay is
# skipped with a message when it is absent).
#   on the H200:      bash bench/run_host_world.sh
#   here on lavapipe: DEVICE= COUNT=2000 BIG=4000 FRAMES=3 WARMUP=1 SIZE=480x270 MESH_CAPACITY=1000 \
#                     COPIES=1 TRAJECTORIES=../shared/trajectories/juelich-bidirectional-corridor.txt \
#                     bash bench/run_host_world.sh
set -uo pipefail
source "$(dirname "${BASH_SOURCE[0]}")/lent_machine.sh"
count=${COUNT:-1000000}
big=${BIG:-10000000}
frames=${FRAMES:-60}
warmup=${WARMUP:-10}
size=${SIZE:-1920x1080}
capacity=${MESH_CAPACITY:-65536}
copies=${COPIES:-100}
parts=${PARTS:-live driven big}
trajectories=${TRAJECTORIES:-.devdata/juelich-bidirectional-corridor.txt}
device=${DEVICE-NVIDIA}
bin=$PWD/.devbin
res=/tmp/host-world
out=${OUT:-/tmp/out}
probe() { "$bin/crowd-bench" "${device_flag[@]}" --quick --methods compute --models soldier --counts 1 \
            --csv "$res/probe.csv" >"$res/probe.txt" 2>&1; }
begin_run run_host_world

failures=0
rows=()
# bench KEY ARGS...: one crowd-bench run of the shared settings; its row joins the table.
bench() {
  local key=$1; shift
  run "$key" "$bin/crowd-bench" "${device_flag[@]}" --methods compute --shadows on --impostors on \
    --mesh-capacity "$capacity" --frames "$frames" --warmup "$warmup" --size "$size" \
    --csv "$res/$key.csv" --json "$res/$key.json" "$@"
  rows+=("$key")
}
has() { [[ " $parts " == *" $1 "* ]]; }

if has live; then
  bench stress-still --scene stress --models soldier --counts "$count"
  bench stress-churn --scene stress --models soldier --counts "$count" --churn 1
  bench mill-still --scene mill --models soldier --counts "$count"
  bench mill-churn --scene mill --models soldier --counts "$count" --churn 1
fi
if has driven; then
  has live || bench mill-still --scene mill --models soldier --counts "$count"
  bench mill-host --scene mill --models soldier --counts "$count" --agents host
  bench mill-device --scene mill --models soldier --counts "$count" --agents device
  has live || bench stress-still --scene stress --models soldier --counts "$count"
  bench stress-hills --scene stress --models soldier --counts "$count" --terrain hills
  if [[ -f $trajectories ]]; then
    bench corridor-replay --scene default --trajectories "$trajectories" --trajectory-copies "$copies" --models soldier \
      --terrain hills --start 40
  else
    echo "corridor replay skipped: no recording at $trajectories"
  fi
fi
if has big; then
  bench big-still-above --scene stress --models soldier --counts "$big" --start 0
  bench big-device-above --scene stress --models soldier --counts "$big" --start 0 --agents device
  bench big-still-inside --scene stress --models soldier --counts "$big" --start 20
  bench big-device-inside --scene stress --models soldier --counts "$big" --start 20 --agents device
fi

{
  echo
  echo "compute, shadows on, impostors on (--mesh-capacity $capacity), $size; medians (and p95) over $frames frames"
  echo "after $warmup warm-up, ms. frame: wall clock between frame starts (two frames in flight); gpu: every pass's"
  echo "GPU time ($(csv_value "$res/${rows[0]}.csv" pass_clock)); drive: the world's driver on the CPU (its own work and"
  echo "its calls); ingest: the library's calls in it (spawn, remove, drive); plan: Crowd::advanceTo; record: the"
  echo "renderer's recording. device: $(tail -1 "$res/nvidia-smi.txt" 2>/dev/null)"
  printf "%-18s %9s | %8s %8s %7s | %8s | %7s %7s %8s %7s %7s %7s\n" run characters median p95 fps gpu \
    drive ingest "p95 ing" plan "p95 pl" record
  for key in "${rows[@]}"; do
    csv=$res/$key.csv
    if [[ $(csv_value "$csv" status) != ok ]]; then
      printf "%-18s | %s\n" "$key" "not run: $(tail -1 "$res/$key.txt")"
      continue
    fi
    printf "%-18s %9s | %8.3f %8.3f %7.1f | %8.3f | %7.3f %7.3f %8.3f %7.3f %7.3f %7.3f\n" "$key" \
      "$(csv_value "$csv" characters)" "$(csv_value "$csv" median_frame_ms)" "$(csv_value "$csv" p95_frame_ms)" \
      "$(csv_value "$csv" fps)" "$(csv_value "$csv" gpu_total_ms)" "$(csv_value "$csv" cpu_drive_ms)" \
      "$(csv_value "$csv" cpu_ingest_ms)" "$(csv_value "$csv" p95_cpu_ingest_ms)" "$(csv_value "$csv" cpu_plan_ms)" \
      "$(csv_value "$csv" p95_cpu_plan_ms)" "$(csv_value "$csv" cpu_record_ms)"
  done
} | tee "$res/summary.txt"
tar -czf "$out/host-world.tgz" -C /tmp host-world
[[ $failures == 0 ]] || { echo "run_host_world: $failures run(s) failed (see their .txt in host-world.tgz)"; exit 1; }
