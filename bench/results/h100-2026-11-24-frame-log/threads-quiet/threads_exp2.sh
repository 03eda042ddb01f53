#!/usr/bin/env bash
for round in 1 2 3; do
  for t in 16 12 8; do
    FLAGS="--threads $t" TAG=t$t-$round RUNS="mill-above" FRAMES=600 WARMUP=60 OUT=$OUT bash .devbin/run_frame_log.sh 2>&1 | grep -v "^==\|name, driver\|NVIDIA H100" | sed "s/^/threads $t $round: /"
  done
done
