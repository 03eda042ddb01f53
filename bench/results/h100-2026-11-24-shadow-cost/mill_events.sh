#!/usr/bin/env bash
# 1,000,000 milling soldiers from above, steady state (from 30 s), events on and off, twice interleaved:
# where the CPU's frame goes (planning, recording).
set -uo pipefail
bin=$(realpath .devbin); res=/tmp/mill-events; out=${OUT:-/tmp/out}; device=NVIDIA
source "$bin/lent_machine.sh"
begin_run mill_events
for r in 1 2; do for ev in on off; do
  run "mill-$ev-$r" "$bin/crowd-bench" "${device_flag[@]}" --scene stress --counts 1000000 --behaviour mill --start 30 \
    --impostors on --methods compute --size 1920x1080 --frames 300 --warmup 30 --events $ev --json "$res/mill-$ev-$r.json"
done; done
jv() { grep -o "\"$2\": *[-0-9.e+]*" "$1" | head -1 | sed 's/.*: *//'; }
for r in 1 2; do for ev in on off; do j=$res/mill-$ev-$r.json
  printf "events %-3s r%s | frame %8.3f p95 %8.3f | plan %7.3f record %7.3f\n" $ev $r "$(jv $j median_frame_ms)" "$(jv $j p95_frame_ms)" \
    "$(jv $j cpu_plan_ms)" "$(jv $j cpu_record_ms)"
done; done | tee "$res/summary.txt"
tar -czf "$out/mill-events.tgz" -C /tmp mill-events
