#!/usr/bin/env bash
# lavapipe (2 cores), stress scene at 20,000 soldiers, 960x540, compute, impostors on and off, from
# above (t = 0 s) and inside (t = 20 s); the mixed scene for the atlas of two models.
set -u
cd "$(dirname "$0")"
bin=../../../build
for start in 0 20; do
  for imp in on off; do
    "$bin/crowd-render" --scene stress --count 20000 --start $start --method compute --size 960x540 --frames 6 \
      --impostors $imp --out stress-20k-t$start-impostors-$imp.png --json stress-20k-t$start-impostors-$imp.json \
      > stress-20k-t$start-impostors-$imp.txt 2>&1
  done
done
"$bin/crowd-render" --scene mixed --size 960x540 --frames 6 --method compute --impostors on \
  --out mixed-impostors-on.png --json mixed-impostors-on.json > mixed-impostors-on.txt 2>&1
