#!/usr/bin/env bash
bash .devbin/plan_ab.sh
for round in 1 2; do
  for build in before after; do
    b=$PWD/.devbin; [[ $build == before ]] && b=$PWD/.devbin/before
    BIN=$b TAG=$build-$round RUNS="mill-above in-place-above mill-inside" OUT=$OUT bash .devbin/run_frame_log.sh 2>&1 | grep -v "^==\|name, driver\|NVIDIA H100" | sed "s/^/$build $round: /"
  done
done
