#!/usr/bin/env bash
# Issue 19 re-measured on a lent GPU machine: with impostors on and more characters qualifying for a
# mesh level than --mesh-capacity, the cap must demote the smallest on screen first. The issue's frame
# (1,000,000 soldiers inside the crowd, t = 20 s, 7680x4320; about 150,000 qualify) with the default
# capacity (65,536) and a smaller one (16,384), each against the same frame with a capacity nobody
# exceeds (300,000: any capacity above the qualifying count draws the same picture, and 300,000 keeps
# compute's skinned positions under a 4 GiB storage-buffer range): the PSNR of the pictures (image-psnr;
# the issue measured 13.7 dB for the default before the fix), the characters demoted ("over the mesh
# cap") and the cull pass's GPU time, which holds the cut's three dispatches. Then 1920x1080 with a
# capacity of 4,096. If .devbin/old/ holds a crowd-render built before the fix (commit bdf1634), the
# default-capacity frames are rendered by it too: the issue's picture again, and the cull pass without
# the cut (the cut's cost is the difference).
# Expects the Vulkan loader packages in .gl/ and prebuilt crowd-render and image-psnr plus their shared
# libraries in .devbin/ (both carried with the call). Logs, JSON, the PSNR lines and the 1920x1080
# pictures land in $OUT/capacity.tgz, a summary on stdout; the 7680x4320 pictures (tens of MB each, over
# what a device call brings back) stay in /tmp/capacity-8k.
# Usage: bench/run_capacity.sh [quick]
set -uo pipefail
for f in .gl/*.deb; do dpkg -x "$f" /; done
ldconfig
export LD_LIBRARY_PATH=$PWD/.devbin${LD_LIBRARY_PATH:+:$LD_LIBRARY_PATH}
bin=.devbin
res=/tmp/capacity
pictures=/tmp/capacity-8k
mkdir -p "$res" "$pictures" "${OUT:-/tmp/out}"
if ! "$bin/crowd-render" --list-devices >"$res/devices.txt" 2>&1 || ! grep -qi nvidia "$res/devices.txt"; then
  export VK_DRIVER_FILES=/usr/local/nvidia/share/vulkan/icd.d/nvidia_icd.json
  "$bin/crowd-render" --list-devices >"$res/devices.txt" 2>&1
fi
cat "$res/devices.txt"
nvidia-smi --query-gpu=name,driver_version,clocks.sm,clocks.mem --format=csv >"$res/nvidia-smi.txt" 2>&1
frames="--frames 30"
[[ "${1:-}" == quick ]] && frames="--frames 5"
picture() { [[ $1 == 8k-* ]] && echo "$pictures/$1.png" || echo "$res/$1.png"; }
render() {  # crowd-render binary, name, crowd-render flags...
  local program=$1 name=$2; shift 2
  echo "== $name: $program --scene stress --method compute --impostors on $frames $*" | tee -a "$res/commands.txt"
  "$program" --device NVIDIA --scene stress --method compute --impostors on $frames "$@" \
    --out "$(picture "$name")" --json "$res/$name.json" >"$res/$name.txt" 2>"$res/$name.err"
  echo "exit $?"
  grep -E "drawn:|gpu:" "$res/$name.txt"
  cat "$res/$name.err"
}
psnr() {  # reference, picture
  echo "-- $2 against $1: $("$bin/image-psnr" "$(picture "$1")" "$(picture "$2")" 2>&1)" | tee -a "$res/psnr.txt"
}
old=$bin/old/crowd-render
issue="--count 1000000 --start 20 --size 7680x4320"
render "$bin/crowd-render" 8k-reference $issue --mesh-capacity 300000
render "$bin/crowd-render" 8k-default $issue
render "$bin/crowd-render" 8k-small $issue --mesh-capacity 16384
psnr 8k-reference 8k-default
psnr 8k-reference 8k-small
if [[ -x $old ]]; then
  render "$old" 8k-default-atomic-order $issue
  psnr 8k-reference 8k-default-atomic-order
fi
hd="--count 1000000 --start 20 --size 1920x1080"
render "$bin/crowd-render" hd-reference $hd --mesh-capacity 300000
render "$bin/crowd-render" hd-small $hd --mesh-capacity 4096
psnr hd-reference hd-small
if [[ -x $old ]]; then
  render "$old" hd-small-atomic-order $hd --mesh-capacity 4096
  psnr hd-reference hd-small-atomic-order
fi
tar czf "${OUT:-/tmp/out}/capacity.tgz" -C /tmp capacity
