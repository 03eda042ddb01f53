#!/usr/bin/env bash
# Issue 20's structure-of-arrays animation jobs on a lent machine's CPU: crowd-bench --palette (the bone
# palettes of a milling soldier crowd on one thread and on every core, the GPU passes beside them) for
# each build given, interleaved, twice, so drift shows. Prints, per round, build and count, the CPU
# milliseconds and M joints/s and the change against the first build of the same round; writes
# $OUT/simd.tgz (outputs, CSVs, JSON, lscpu).
#
# Builds: BINS (".devbin"), folders each holding crowd-bench and the shared libraries it loads (see
# docs/embedding-example.md), the first the baseline. For before and after, carry a build of 85a5d23
# (the scalar jobs) as .devbin-scalar and give BINS=".devbin-scalar .devbin".
# Expects the Vulkan loader packages in .gl/ (carried).
#   on the H100:      BINS=".devbin-scalar .devbin" bash bench/run_simd.sh
#   here on lavapipe: DEVICE= COUNTS=1024,4096 BINS="/tmp/scalar-build build" bash bench/run_simd.sh
# COUNTS (1024,16384,262144,1000000): crowd-bench's --counts; DEVICE (NVIDIA): part of the device's
# name, empty for the first device.
set -uo pipefail
source "$(dirname "${BASH_SOURCE[0]}")/lent_machine.sh"
counts=${COUNTS:-1024,16384,262144,1000000}
device=${DEVICE-NVIDIA}
read -r -a bins <<<"${BINS:-.devbin}"
res=/tmp/simd
out=${OUT:-/tmp/out}
rm -rf "$res"
mkdir -p "$res" "$out"
install_vulkan_loader
device_flag=()
[[ -n $device ]] && device_flag=(--device "$device")
# A build's folder, relative to the repository root unless absolute.
folder() { [[ $1 == /* ]] && echo "$1" || echo "$PWD/$1"; }
first=$(folder "${bins[0]}")
probe() { LD_LIBRARY_PATH=$first "$first/crowd-bench" "${device_flag[@]}" --counts 1 --frames 1 --warmup 0 --size 64x64 >"$res/probe.txt" 2>&1; }
find_device run_simd quiet
lscpu >"$res/lscpu.txt" 2>&1
failures=0
for round in 1 2; do
  for b in "${!bins[@]}"; do
    bin=$(folder "${bins[$b]}")
    cmd=("$bin/crowd-bench" "${device_flag[@]}" --palette --models soldier --counts "$counts"
         --csv "$res/palette-$b-$round.csv" --json "$res/palette-$b-$round.json")
    echo "${cmd[*]}" >>"$res/commands.txt"
    echo "== ${bins[$b]}, round $round"
    LD_LIBRARY_PATH=$bin "${cmd[@]}" >"$res/palette-$b-$round.txt" 2>&1 || {
      failures=$((failures + 1)); echo "   failed:"; tail -3 "$res/palette-$b-$round.txt"; }
  done
done

# Rows of the palette CSV $1 as "characters threads ms1 jps1 msAll jpsAll" (these columns come before
# the quoted ones, so splitting on commas is safe).
rows() {
  awk -F, 'NR == 1 { for (i = 1; i <= NF; i++) c[$i] = i; next }
           $c["status"] == "ok" { print $c["characters"], $c["cpu_threads"], $c["cpu_1_thread_palette_ms"],
             $c["cpu_1_thread_joints_per_s"], $c["cpu_all_threads_palette_ms"], $c["cpu_all_threads_joints_per_s"] }' "$1" 2>/dev/null
}
{
  echo "crowd-bench --palette --models soldier: CPU wall clock, median of 3 runs after a warm-up; $(nproc) CPUs,"
  echo "$(awk -F: '/Model name/ { gsub(/^ +/, "", $2); print $2; exit }' "$res/lscpu.txt");"
  echo "x: speed against ${bins[0]} in the same round"
  printf "%-16s %1s %10s %7s | %10s %8s %6s | %10s %8s %6s\n" build r characters threads "1 thr ms" "Mj/s" x "all ms" "Mj/s" x
  for round in 1 2; do
    for b in "${!bins[@]}"; do
      while read -r chars threads ms1 jps1 msall jpsall; do
        read -r _ _ base1 _ baseall _ < <(rows "$res/palette-0-$round.csv" | awk -v n="$chars" '$1 == n')
        printf "%-16s %1s %10s %7s | %10.3f %8.1f %6s | %10.3f %8.1f %6s\n" "${bins[$b]}" "$round" "$chars" "$threads" \
          "$ms1" "$(awk -v j="$jps1" 'BEGIN { print j / 1e6 }')" "$(awk -v a="$base1" -v b="$ms1" 'BEGIN { printf "%.2f", a / b }')" \
          "$msall" "$(awk -v j="$jpsall" 'BEGIN { print j / 1e6 }')" "$(awk -v a="$baseall" -v b="$msall" 'BEGIN { printf "%.2f", a / b }')"
      done < <(rows "$res/palette-$b-$round.csv")
    done
  done
} | tee "$res/summary.txt"
tar -czf "$out/simd.tgz" -C /tmp simd
[[ $failures == 0 ]] || { echo "run_simd: $failures run(s) failed (see their .txt in simd.tgz)"; exit 1; }
