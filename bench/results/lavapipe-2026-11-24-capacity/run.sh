#!/usr/bin/env bash
# lavapipe (2 cores), issue 19 at lavapipe's scale: the stress scene at 20,000 soldiers inside the crowd
# (t = 20 s), 960x540, compute, impostors on, with --mesh-capacity 1000 (1,418 of the 2,418 characters
# that qualify for a mesh level are demoted) against 10000 (none is; the most lavapipe's 128 MiB
# storage-buffer range allows), and the PSNR between them. OLD=<build dir> runs a build from before the
# fix too (commit bdf1634: demoted in the order of the GPU's atomics).
set -u
cd "$(dirname "$0")"
run() {  # label, build dir
  for cap in 10000 1000; do
    "$2/crowd-render" --scene stress --count 20000 --start 20 --method compute --size 960x540 --frames 3 \
      --impostors on --mesh-capacity $cap --out $1-capacity-$cap.png > $1-capacity-$cap.txt 2>&1
  done
  echo "$1: $(../../../build/image-psnr $1-capacity-10000.png $1-capacity-1000.png)" | tee -a psnr.txt
}
rm -f psnr.txt
run farthest-first ../../../build
[[ -n "${OLD:-}" ]] && run atomic-order "$OLD"
[[ -n "${OLD:-}" ]] && echo "no demotion, the two builds: $(../../../build/image-psnr atomic-order-capacity-10000.png farthest-first-capacity-10000.png)" | tee -a psnr.txt
