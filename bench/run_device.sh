#!/usr/bin/env bash
# Runs the benchmark on a lent GPU machine (see docs/benchmarks.md). Expects the Vulkan loader
# packages in .gl/ and prebuilt crowd-bench / crowd-render in .devbin/ (both carried with the call),
# writes everything under $OUT. Usage: bench/run_device.sh [extra crowd-bench flags]
set -uo pipefail
for f in .gl/*.deb; do dpkg -x "$f" /; done
ldconfig
bin=.devbin
out=${OUT:-/tmp/out}
mkdir -p "$out"
if ! "$bin/crowd-render" --list-devices >"$out/devices.txt" 2>&1 || ! grep -qi nvidia "$out/devices.txt"; then
  export VK_DRIVER_FILES=/usr/local/nvidia/share/vulkan/icd.d/nvidia_icd.json
  "$bin/crowd-render" --list-devices >"$out/devices.txt" 2>&1
fi
cat "$out/devices.txt"
nvidia-smi --query-gpu=name,driver_version,clocks.sm,clocks.mem --format=csv >"$out/nvidia-smi.txt" 2>&1
"$bin/crowd-bench" --device NVIDIA --csv "$out/bench.csv" --json "$out/bench.json" "$@" >"$out/bench.txt" 2>"$out/bench.err"
echo "crowd-bench exit $?"
cat "$out/bench.txt"
