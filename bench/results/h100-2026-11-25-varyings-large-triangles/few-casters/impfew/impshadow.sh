#!/usr/bin/env bash
# H100: few impostor casters and a map fitted to them (stress, every character an impostor): the shadow
# pass with the impostor casters in compute against the hardware path.
set -uo pipefail
bin=$(realpath .devbin); res=/tmp/impfew; out=${OUT:-/tmp/out}; device=NVIDIA
source "$bin/lent_machine.sh"
begin_run impfew QUIET
failures=0
for sr in compute hardware; do
  key=impfew-$sr
  run "$key" "$bin/var-${V:-chunk}/crowd-bench" "${device_flag[@]}" --scene stress --counts 1,16,64,256,1024,16384 --impostors on --impostor-threshold 100000 \
    --lod-thresholds 300000,200000 --methods compute --shadow-raster $sr --frames 100 --warmup 10 --size 1920x1080 --csv "$res/$key.csv"
  awk -F, -v k="$key" 'NR == 1 { for (i = 1; i <= NF; ++i) c[$i] = i; next }
    { printf "%-18s %7s | frame %7.3f | shadow %7.3f draw %6.3f | shadow impostors %s\n", k, $c["characters"], $c["median_frame_ms"], $c["gpu_shadow_ms"], $c["gpu_draw_ms"], $c["shadow_impostors"] }' "$res/$key.csv" | tee -a "$res/summary.txt"
done
tar -czf "$out/impfew.tgz" -C /tmp impfew
echo "failures: $failures"
