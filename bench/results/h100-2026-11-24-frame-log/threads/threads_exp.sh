#!/usr/bin/env bash
for round in 1 2; do
  for t in 16 14 12; do
    FLAGS="--threads $t" TAG=threads$t-$round RUNS="mill-above mill-inside" OUT=$OUT bash .devbin/run_frame_log.sh 2>&1 | grep -v "^==\|name, driver\|NVIDIA H100" | sed "s/^/threads $t $round: /"
  done
done
