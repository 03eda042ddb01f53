#!/usr/bin/env bash
# Impostor shadow casters in compute (var-imp) against main (the hardware draws them), H100.
set -uo pipefail
bin=$(realpath .devbin); res=/tmp/impshadow; out=${OUT:-/tmp/out}; device=NVIDIA
source "$bin/lent_machine.sh"
begin_run impshadow QUIET
echo "commands: crowd-bench --scene stress ... --impostors on --methods compute --size 1920x1080 (before: .devbin = main, after: .devbin/var-imp)" >"$res/summary.txt"
for r in 1 2; do
  for cfg in "inplace-inside:--counts 1000000 --behaviour in-place --start 20 --frames 600 --warmup 60" \
             "mill-inside:--counts 1000000 --behaviour mill --start 20 --frames 600 --warmup 60" \
             "1m-above:--counts 1000000 --frames 200 --warmup 20" \
             "10m-inside:--counts 10000000 --start 20 --frames 200 --warmup 20" \
             "10m-above:--counts 10000000 --frames 200 --warmup 20"; do
    name=${cfg%%:*}
    for v in before after; do
      b=$bin; [[ $v == after ]] && b=$bin/var-imp
      key=$name-$v-$r
      # shellcheck disable=SC2086
      run "$key" "$b/crowd-bench" "${device_flag[@]}" --scene stress ${cfg#*:} --impostors on --methods compute --size 1920x1080 \
        --csv "$res/$key.csv" --frame-log "$res/$key-frames.csv"
      python3 - "$res/$key-frames.csv" "$key" "$(csv_value "$res/$key.csv" median_frame_ms)" "$(csv_value "$res/$key.csv" p95_frame_ms)" <<'PY' | tee -a "$res/summary.txt"
import csv, sys, statistics
rows = list(csv.DictReader(open(sys.argv[1])))
early = [r for r in rows if float(r["scene_seconds"]) < 23.0 and int(r["shadow_impostors"]) > 0]
shadow = statistics.median(float(r["gpu_shadow_ms"]) for r in rows)
line = "%-22s | frame %7.3f p95 %7.3f ratio %.2f | shadow median %.3f" % (sys.argv[2], float(sys.argv[3]), float(sys.argv[4]), float(sys.argv[4]) / float(sys.argv[3]), shadow)
if early:
    line += " | frames with impostor casters before 23 s: %d, their shadow pass %.3f ms, interval %.3f ms, casters %d" % (
        len(early), statistics.median(float(r["gpu_shadow_ms"]) for r in early), statistics.median(float(r["interval_ms"]) for r in early),
        statistics.median(int(r["shadow_impostors"]) for r in early))
print(line)
PY
    done
  done
done
for v in before after; do
  b=$bin; [[ $v == after ]] && b=$bin/var-imp
  run "pic-$v" "$b/crowd-render" "${device_flag[@]}" --scene stress --count 1000000 --start 21 --impostors on --method compute --frames 30 --size 1920x1080 --out "$res/inside-$v.png"
done
"$bin/image-psnr" "$res/inside-before.png" "$res/inside-after.png" | tee -a "$res/summary.txt"
cp "$res/inside-after.png" "$out/"
rm -f "$res"/*.png
tar -czf "$out/impshadow.tgz" -C /tmp impshadow
