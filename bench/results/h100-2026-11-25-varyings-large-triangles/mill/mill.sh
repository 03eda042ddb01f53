#!/usr/bin/env bash
# H100: the milling 1,000,000 inside the crowd, p95 against the median: main (var-main) against packed
# varyings and large shadow triangles shared out (var-chunk); two rounds, builds interleaved.
set -uo pipefail
bin=$(realpath .devbin); res=/tmp/mill; out=${OUT:-/tmp/out}; device=NVIDIA
source "$bin/lent_machine.sh"
begin_run mill QUIET
failures=0
for round in 1 2; do
  for v in main chunk; do
    key=mill-inside-$v-$round
    run "$key" "$bin/var-$v/crowd-bench" "${device_flag[@]}" --scene stress --counts 1000000 --behaviour mill --start 20 --impostors on \
      --methods compute --size 1920x1080 --frames 600 --warmup 60 --csv "$res/$key.csv"
    printf "%-24s | frame %7.3f p95 %7.3f ratio %5.2f\n" "$key" "$(csv_value "$res/$key.csv" median_frame_ms)" "$(csv_value "$res/$key.csv" p95_frame_ms)" \
      "$(awk -F, 'NR==1{for(i=1;i<=NF;++i)c[$i]=i;next}{printf "%.3f", $c["p95_frame_ms"]/$c["median_frame_ms"]}' "$res/$key.csv")" | tee -a "$res/summary.txt"
  done
done
tar -czf "$out/mill.tgz" -C /tmp mill
echo "failures: $failures"
