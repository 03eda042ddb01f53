#!/usr/bin/env bash
# Planning alone (no device): a milling 1,000,000, advanceTo per 60 Hz frame from 30 s, before and after.
export LD_LIBRARY_PATH=$PWD/.devbin
for round in 1 2; do
  for build in before after; do
    bin=.devbin/plan_prof; [[ $build == before ]] && bin=.devbin/plan_prof_before
    for cpus in 0 0-3 0-15; do echo "$build round $round cpus $cpus: $(taskset -c $cpus $bin 1000000 240)"; done
  done
done
