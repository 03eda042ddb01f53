#!/usr/bin/env bash
# Issue 19's anti-aliasing measured on a lent GPU machine. Pictures: the default scene, paper-fig4 and
# paper-fig5 at 1280x720 (and, as in the issue's table, stress 1,000,000 from above with impostors at
# 1920x1080; and stress 100,000 inside the crowd at 1280x720, the frame whose cost is timed), each with --aa off, msaa2, msaa4 and msaa8, against a 4x4 supersampled render of the
# same frame (crowd-render at 4x the width and height, box-filtered down in linear light by
# image-downsample), compared by image-psnr; and against a second reference that also scales the
# pixel thresholds of the levels of detail and impostors by 4 (--lod-thresholds 600,200
# --impostor-threshold 128), so that it draws each character at the level the 1x frame does: the
# first reference's finer levels differ from the 1x frame by more than its edges do. Cost: crowd-bench on paper-fig4 and stress 100,000
# inside the crowd (--start 20) at 1920x1080 with each --aa, per method (compute, two-pass),
# interleaved, twice, so drift shows; the frame's median and the GPU total against --aa off.
# Prints the PSNR table and the cost table, and writes $OUT/aa.tgz (every run's output and the CSVs) and
# $OUT/aa-pictures.tgz (the pictures and the references brought down; the 4x renders stay in /tmp/aa-4x).
#
# Expects the Vulkan loader packages in .gl/ and crowd-render, crowd-bench, image-psnr and
# image-downsample with their shared libraries in .devbin/ (carried).
#   on the H100:      bash bench/run_aa.sh
#   here on lavapipe: DEVICE= FRAMES=3 WARMUP=1 PICTURE_FRAMES=1 SIZE=320x180 BENCH_SIZE=320x180 \
#                     STRESS_COUNT=8000 STRESS_PICTURE_COUNT=8000 STRESS_SIZE=320x180 LEVELS="off msaa4" \
#                     bash bench/run_aa.sh
# EXTRA: flags added to the 1x pictures and the timed runs but not to the references, e.g.
# EXTRA="--lod-thresholds 75,25" (finer levels of detail against the same references).
# FRAMES (default 300) and WARMUP (30): crowd-bench's --frames and --warmup; PICTURE_FRAMES (30):
# crowd-render's --frames (the picture is the last frame's); DEVICE (NVIDIA): part of the device's
# name, empty for the first device; SIZE (1280x720): the pictures'; BENCH_SIZE (1920x1080): the
# timings'; STRESS_COUNT (100000): the timed stress crowd; STRESS_PICTURE_COUNT (1000000; 0 leaves
# that picture out) and STRESS_SIZE (1920x1080): the stress picture's; INSIDE_PICTURE_COUNT (100000; 0
# leaves it out): the crowd of the picture inside it, at SIZE; LEVELS ("off msaa2 msaa4
# msaa8"): the --aa values, off first.
# PARTS ("pictures cost"): "pictures" or "cost" alone, to split the run over two device calls (each
# call has 10 minutes; the whole run may need more).
set -uo pipefail
source "$(dirname "${BASH_SOURCE[0]}")/lent_machine.sh"
frames=${FRAMES:-300}
warmup=${WARMUP:-30}
picture_frames=${PICTURE_FRAMES:-30}
device=${DEVICE-NVIDIA}
size=${SIZE:-1280x720}
bench_size=${BENCH_SIZE:-1920x1080}
stress_count=${STRESS_COUNT:-100000}
stress_picture_count=${STRESS_PICTURE_COUNT:-1000000}
stress_size=${STRESS_SIZE:-1920x1080}
inside_picture_count=${INSIDE_PICTURE_COUNT:-100000}
read -r -a levels <<<"${LEVELS:-off msaa2 msaa4 msaa8}"
# Flags for the 1x pictures and the timed runs, not the references (e.g. EXTRA="--lod-thresholds 75,25":
# what finer levels of detail gain against the same references, and cost).
read -r -a extra_flags <<<"${EXTRA:-}"
parts=${PARTS:-pictures cost}
bin=$PWD/.devbin
res=/tmp/aa
big=/tmp/aa-4x
out=${OUT:-/tmp/out}
rm -rf "$res" "$big"
mkdir -p "$res" "$big" "$out"
install_vulkan_loader
export LD_LIBRARY_PATH=$bin${LD_LIBRARY_PATH:+:$LD_LIBRARY_PATH}
device_flag=()
[[ -n $device ]] && device_flag=(--device "$device")
# The device by name, or the NVIDIA driver is not among the loader's: name its ICD.
probe() { "$bin/crowd-render" "${device_flag[@]}" --count 1 --frames 1 --size 64x64 --aa off --out "$res/probe.png" >"$res/probe.txt" 2>&1; }
find_device run_aa

failures=0
# WxH times 4 in each direction.
times4() { local w=${1%x*} h=${1#*x}; echo "$((w * 4))x$((h * 4))"; }

# ---- Pictures against the supersampled render ----
[[ $parts == *pictures* ]] || pictures_skipped=1
pictures=("default|--scene default|$size" "paper-fig4|--scene paper-fig4|$size" "paper-fig5|--scene paper-fig5|$size")
if [[ $stress_picture_count != 0 ]]; then
  pictures+=("stress-above|--scene stress --count $stress_picture_count --impostors on --method compute|$stress_size")
fi
if [[ $inside_picture_count != 0 ]]; then
  pictures+=("stress-inside|--scene stress --count $inside_picture_count --start 20 --method compute|$size")
fi
same_lod=(--lod-thresholds "600,200" --impostor-threshold 128)  # the defaults (150,50 and 32) x 4
for entry in "${pictures[@]}"; do
  [[ -n ${pictures_skipped:-} ]] && break
  IFS='|' read -r name flags picture_size <<<"$entry"
  for reference in supersampled same-lod; do
    extra=(); [[ $reference == same-lod ]] && extra=("${same_lod[@]}")
    # The reference cuts every impostor at half coverage (--far-crowd off): the far layer is itself an
    # average, so a reference made with it would grade the layer against itself.
    # shellcheck disable=SC2086  # flags are words
    run "$name-4x-$reference" "$bin/crowd-render" "${device_flag[@]}" $flags "${extra[@]}" --frames "$picture_frames" \
      --aa off --far-crowd off --size "$(times4 "$picture_size")" --out "$big/$name-4x-$reference.png" &&
      run "$name-downsample-$reference" "$bin/image-downsample" "$big/$name-4x-$reference.png" 4 \
        "$res/$name-$reference.png"
  done
  for aa in "${levels[@]}"; do
    # shellcheck disable=SC2086
    run "$name-$aa" "$bin/crowd-render" "${device_flag[@]}" $flags "${extra_flags[@]}" --frames "$picture_frames" --aa "$aa" \
      --size "$picture_size" --out "$res/$name-$aa.png" || continue
    for reference in supersampled same-lod; do
      "$bin/image-psnr" "$res/$name-$reference.png" "$res/$name-$aa.png" >"$res/$name-$aa-$reference.psnr" 2>&1
    done
  done
done

# ---- Cost ----
# Percent by which $2 is over $1.
percent() { awk -v a="$1" -v b="$2" 'BEGIN { if (a + 0 > 0 && b != "") printf "%+.1f%%", 100 * (b - a) / a; else print "-" }'; }
scene_flags() {
  case $1 in
    paper-fig4) echo "--scene paper-fig4" ;;
    stress) echo "--scene stress --counts $stress_count --start 20" ;;
  esac
}
for round in 1 2; do
  [[ $parts == *cost* ]] || break
  for scene in paper-fig4 stress; do
    for method in compute two-pass; do
      for aa in "${levels[@]}"; do
        key=$scene-$method-$aa-$round
        # shellcheck disable=SC2046  # scene_flags gives words
        run "bench-$key" "$bin/crowd-bench" "${device_flag[@]}" $(scene_flags $scene) "${extra_flags[@]}" --methods $method --aa "$aa" \
          --frames "$frames" --warmup "$warmup" --size "$bench_size" --csv "$res/bench-$key.csv"
      done
    done
  done
done

{
  for reference in supersampled same-lod; do
    echo
    if [[ $reference == supersampled ]]; then
      echo "PSNR against the 4x4 supersampled render (crowd-render at 4x the width and height, --aa off, box-filtered"
      echo "down in linear light; the issue's measure), last of $picture_frames frames, dB:"
    else
      echo "PSNR against the same with the level-of-detail and impostor thresholds x 4 (${same_lod[*]}):"
      echo "each character at the level the 1x frame draws it, so that what differs is sampling, dB:"
    fi
    printf "%-14s %-10s" picture size
    for aa in "${levels[@]}"; do printf " %11s" "$aa"; done
    echo
    for entry in "${pictures[@]}"; do
      IFS='|' read -r name flags picture_size <<<"$entry"
      printf "%-14s %-10s" "$name" "$picture_size"
      for aa in "${levels[@]}"; do
        printf " %11s" "$(sed -n 's/^PSNR \([^ ]*\) dB.*/\1/p' "$res/$name-$aa-$reference.psnr" 2>/dev/null)"
      done
      echo
    done
  done
  echo
  echo "Cost: crowd-bench medians over $frames frames after $warmup warm-up at $bench_size, ms; gpu: its GPU total"
  echo "($(csv_value "$res/bench-paper-fig4-compute-off-1.csv" pass_clock)), draw: its draw pass (the colour pass), frame: wall clock"
  echo "between frame starts, two frames in flight; +%: against --aa off of the same round."
  echo "filter: the edge filter's pass (--aa fxaa)."
  printf "%-10s %-8s %-10s %1s | %8s %7s | %8s %7s | %8s %7s | %6s\n" scene method aa r gpu "+%" draw "+%" frame "+%" filter
  for round in 1 2; do
    for scene in paper-fig4 stress; do
      for method in compute two-pass; do
        base=$res/bench-$scene-$method-off-$round.csv
        base_gpu=$(csv_value "$base" gpu_total_ms) base_draw=$(csv_value "$base" gpu_draw_ms)
        base_frame=$(csv_value "$base" median_frame_ms)
        for aa in "${levels[@]}"; do
          csv=$res/bench-$scene-$method-$aa-$round.csv
          gpu='' draw='' frame='' filter=''
          if [[ $(csv_value "$csv" status) == ok ]]; then  # a skipped row has zeros
            gpu=$(csv_value "$csv" gpu_total_ms) draw=$(csv_value "$csv" gpu_draw_ms) frame=$(csv_value "$csv" median_frame_ms)
            filter=$(csv_value "$csv" gpu_edge_filter_ms)
          fi
          printf "%-10s %-8s %-10s %1s | %8s %7s | %8s %7s | %8s %7s | %6s\n" "$scene" "$method" "$aa" "$round" \
            "${gpu:--}" "$(percent "$base_gpu" "$gpu")" "${draw:--}" "$(percent "$base_draw" "$draw")" \
            "${frame:--}" "$(percent "$base_frame" "$frame")" "${filter:--}"
        done
      done
    done
  done
} | tee "$res/summary.txt"
tar -czf "$out/aa.tgz" -C /tmp --exclude='*.png' aa
(cd /tmp && shopt -s nullglob && pictures_made=(aa/*.png) && [[ ${#pictures_made[@]} == 0 ]] ||
  tar -czf "$out/aa-pictures.tgz" "${pictures_made[@]}")
[[ $failures == 0 ]] || { echo "run_aa: $failures run(s) failed (see their .txt in aa.tgz)"; exit 1; }
