#!/usr/bin/env bash
# The library split's cost on a lent GPU machine: the same frames through the commit before the split
# (.devbin/old/) and through the public record calls (.devbin/), interleaved twice so drift shows, then
# the memory planner against what each method allocated. Expects the Vulkan loader packages in .gl/
# and both builds with their shared libraries in .devbin/ (carried). Writes $OUT/library.tgz.
set -uo pipefail
for f in .gl/*.deb; do dpkg -x "$f" /; done
ldconfig
export LD_LIBRARY_PATH=$PWD/.devbin${LD_LIBRARY_PATH:+:$LD_LIBRARY_PATH}
res=/tmp/library
mkdir -p "$res" "${OUT:-/tmp/out}"
if ! .devbin/crowd-render --list-devices >"$res/devices.txt" 2>&1 || ! grep -qi nvidia "$res/devices.txt"; then
  export VK_DRIVER_FILES=/usr/local/nvidia/share/vulkan/icd.d/nvidia_icd.json
  .devbin/crowd-render --list-devices >"$res/devices.txt" 2>&1
fi
cat "$res/devices.txt"
nvidia-smi --query-gpu=name,driver_version,clocks.sm,clocks.mem --format=csv >"$res/nvidia-smi.txt" 2>&1
run() {  # build (old|new), name, crowd-bench flags...
  local build=$1 name=$2; shift 2
  local bin=.devbin; [[ $build == old ]] && bin=.devbin/old
  echo "== $build $name: crowd-bench $*" | tee -a "$res/commands.txt"
  "$bin/crowd-bench" --device NVIDIA --frames 300 --warmup 30 --json "$res/$build-$name.json" "$@" \
    >"$res/$build-$name.txt" 2>&1
  grep -E "^ *(compute|two-pass|vs)" "$res/$build-$name.txt" | head -3
}
for round in 1 2; do
  for build in old new; do
    run $build "fig4-$round" --scene paper-fig4 --size 1920x1080 --methods compute,two-pass
    run $build "stress100k-$round" --scene stress --counts 100000 --start 20 --size 1920x1080 --methods compute
  done
done
for method in two-pass two-pass-direct vs vs-instanced compute static; do
  echo "== memory $method" | tee -a "$res/memory.txt"
  .devbin/crowd-render --device NVIDIA --scene paper-fig4 --method $method --size 1920x1080 --frames 3 \
    --out "$res/fig4-$method.png" 2>&1 | grep "library memory" | tee -a "$res/memory.txt"
done
.devbin/crowd-render --device NVIDIA --scene stress --count 1000000 --impostors on --method compute --size 1920x1080 \
  --frames 3 --out "$res/stress-1m.png" 2>&1 | grep "library memory" | sed 's/^/impostors 1M: /' | tee -a "$res/memory.txt"
tar -czf "${OUT:-/tmp/out}/library.tgz" -C /tmp library
