#!/usr/bin/env bash
# What Crowd::events costs a frame on a lent machine's CPU (issue 20): event-bench (CPU only) for
# COUNT walking soldiers, in place and milling, each 60 Hz frame's window asked for the whole crowd on
# 1, 4 and every core's threads; twice, so drift shows. Prints the tables; writes $OUT/event-queries.tgz
# (outputs, commands, lscpu).
#
# Expects event-bench in .devbin/ with the shared libraries it loads (carried; the same three as
# crowd-bench's, docs/embedding-example.md: cp build/event-bench .devbin/ and cp -L libtinygltf.so.2d,
# libmeshoptimizer.so.2d, libstb.so.0 from /lib/x86_64-linux-gnu); it needs no Vulkan device.
#   on the H100:      bash bench/run_event_queries.sh
#   here (2 cores):   COUNT=10000 FRAMES=30 THREADS=1,2 bash bench/run_event_queries.sh
# COUNT (100000), FRAMES (120: event-bench's --frames), THREADS (1,4,<cores>: its --threads).
set -uo pipefail
source "$(dirname "${BASH_SOURCE[0]}")/lent_machine.sh"
count=${COUNT:-100000}
frames=${FRAMES:-120}
threads=${THREADS:-1,4,$(nproc)}
device=  # CPU only: no device to find
bin=$PWD/.devbin
[[ -x $bin/event-bench ]] || bin=$PWD/build  # here: the build folder
[[ -x $bin/event-bench ]] || { echo "run_event_queries: no event-bench in .devbin/ or build/"; exit 1; }
res=/tmp/event-queries
out=${OUT:-/tmp/out}
probe() { "$bin/event-bench" --count 16 --frames 1 --threads 1 >"$res/probe.txt" 2>&1; }
begin_run run_event_queries quiet
lscpu >"$res/lscpu.txt" 2>&1
failures=0
for round in 1 2; do
  run "events-$round" "$bin/event-bench" --count "$count" --frames "$frames" --threads "$threads"
done
{
  echo
  echo "$(grep -m1 'Model name' "$res/lscpu.txt" | sed 's/  */ /g'), $(nproc) cores"
  for round in 1 2; do
    echo "-- round $round"
    cat "$res/events-$round.txt"
  done
} | tee "$res/summary.txt"
tar -czf "$out/event-queries.tgz" -C /tmp event-queries
[[ $failures == 0 ]] || { echo "run_event_queries: $failures run(s) failed (see their .txt in event-queries.tgz)"; exit 1; }
