#!/usr/bin/env bash
# The GPU-driven frame's measurements on a lent GPU machine: the paper's scenes (Fig. 3, 4, 5), the
# mixed crowd and the stress scaling, every method, 1920x1080, then Table 1 again (1280x720).
# Expects the Vulkan loader packages in .gl/ and prebuilt binaries plus their shared libraries in
# .devbin/ (both carried with the call). Everything lands in $OUT/scenes.tgz (the device tool brings
# back few files), with a summary on stdout. Two parts, each well inside one call's 10 minutes:
# Usage: bench/run_scenes.sh scenes|stress|shadows|impostors|impostors-off|living [quick]
set -uo pipefail
for f in .gl/*.deb; do dpkg -x "$f" /; done
ldconfig
export LD_LIBRARY_PATH=$PWD/.devbin${LD_LIBRARY_PATH:+:$LD_LIBRARY_PATH}
bin=.devbin
part=${1:-scenes}
res=/tmp/$part
mkdir -p "$res" "${OUT:-/tmp/out}"
if ! "$bin/crowd-render" --list-devices >"$res/devices.txt" 2>&1 || ! grep -qi nvidia "$res/devices.txt"; then
  export VK_DRIVER_FILES=/usr/local/nvidia/share/vulkan/icd.d/nvidia_icd.json
  "$bin/crowd-render" --list-devices >"$res/devices.txt" 2>&1
fi
cat "$res/devices.txt"
nvidia-smi --query-gpu=name,driver_version,clocks.sm,clocks.mem --format=csv >"$res/nvidia-smi.txt" 2>&1
frames="--frames 60 --warmup 10"
[[ "${2:-}" == quick ]] && frames="--frames 5 --warmup 2"
bench() {  # name, crowd-bench flags...
  local name=$1; shift
  echo "== $name: crowd-bench $*" | tee -a "$res/commands.txt"
  "$bin/crowd-bench" --device NVIDIA $frames --csv "$res/$name.csv" --json "$res/$name.json" "$@" \
    >"$res/$name.txt" 2>"$res/$name.err"
  echo "exit $?"
  grep -A40 "^Per pass" "$res/$name.txt" | cut -c1-200
}
hd="--size 1920x1080"
if [[ $part == shadows ]]; then
  # Skin once, draw twice: Table 1 and Fig. 4 with the shadow map on and off, every method.
  bench table1-shadows --counts 1,16,64,256,1024,2048,4096,16384 --shadows on
  bench table1-no-shadows --counts 1,16,64,256,1024,2048,4096,16384 --shadows off
  bench fig4-shadows --scene paper-fig4 $hd --shadows on
  bench fig4-no-shadows --scene paper-fig4 $hd --shadows off
  "$bin/crowd-render" --device NVIDIA --scene paper-fig4 --method compute --size 1920x1080 --frames 600 \
    --out "$res/paper-fig4-shadows.png" --json "$res/paper-fig4-shadows.json" >"$res/paper-fig4-shadows.txt" 2>&1
elif [[ $part == impostors || $part == impostors-off ]]; then
  # The impostor level (issue 11): stress at 1, 2 and 4 million soldiers from high over the crowd
  # (t = 0 s) and from inside it (t = 20 s), compute skinning, one JSON per run; `impostors-off` is the
  # same without them (the speed-up), with fewer frames since those frames take up to a second.
  if [[ $part == impostors ]]; then flags="--impostors on"; else flags="--impostors off"; frames="--frames 10 --warmup 3"; fi
  [[ "${2:-}" == quick ]] && frames="--frames 5 --warmup 2"
  for count in 1000000 2000000 4000000; do
    bench "stress-over-$count-$part" --scene stress $hd --methods compute --counts $count $flags
    bench "stress-inside-$count-$part" --scene stress $hd --start 20 --methods compute --counts $count $flags
  done
  # Pictures for the image difference (the same frame with impostors on and off), 1,000,000 soldiers.
  for start in 0 20; do
    "$bin/crowd-render" --device NVIDIA --scene stress --count 1000000 --start $start --method compute \
      --size 1920x1080 --frames 30 $flags --out "$res/stress-1m-t$start-$part.png" \
      --json "$res/stress-1m-t$start-$part-render.json" >"$res/stress-1m-t$start-$part-render.txt" 2>&1
  done
elif [[ $part == living ]]; then
  # The living crowd (issue 10): bone palettes of a milling crowd, 1,024 to 1,000,000 soldiers, on the
  # CPU (one thread, every thread) and the GPU; then the whole frame at 100,000 soldiers inside the
  # crowd, milling (moving, crossfading) against looping in place, GPU and CPU animation.
  "$bin/crowd-bench" --device NVIDIA --palette --models soldier --json "$res/palettes.json" \
    >"$res/palettes.txt" 2>"$res/palettes.err"
  echo "palettes exit $?"; cat "$res/palettes.txt"
  for behaviour in in-place mill; do
    for animation in gpu cpu; do
      bench "stress-inside-100k-$behaviour-$animation" --scene stress $hd --start 20 --methods compute \
        --counts 100000 --behaviour $behaviour --animation $animation
    done
  done
  for scene in mill march; do
    "$bin/crowd-render" --device NVIDIA --scene "$scene" --method compute --size 1920x1080 --frames 600 \
      --out "$res/$scene.png" --json "$res/$scene-render.json" >"$res/$scene-render.txt" 2>&1
  done
elif [[ $part == scenes ]]; then
  bench fig3 --scene paper-fig3 $hd
  bench fig4 --scene paper-fig4 $hd
  bench fig5 --scene paper-fig5 $hd
  bench mixed --scene mixed $hd
  bench table1 --counts 1,16,64,256,1024,2048,4096,16384
else
  # 100,000 soldiers from high over the crowd (the whole crowd in view), every method; then the
  # largest crowds that hold 60 fps seen from above (t = 0 s) and from inside the crowd (t = 20 s).
  bench stress-all --scene stress $hd --counts 100000
  bench stress-over --scene stress $hd --methods compute,static --counts 25000,50000,75000
  bench stress-inside --scene stress $hd --start 20 --methods compute,static,vs-instanced \
    --counts 100000,250000,500000,1000000,2000000
  # Pictures as the H100 draws them (frame 600: 10 s into each camera path).
  for scene in paper-fig3 paper-fig4 paper-fig5 mixed stress; do
    "$bin/crowd-render" --device NVIDIA --scene "$scene" --method compute --size 1920x1080 --frames 600 \
      --out "$res/$scene.png" --json "$res/$scene-render.json" >"$res/$scene-render.txt" 2>&1
  done
  "$bin/crowd-render" --device NVIDIA --scene stress --start 20 --method compute --size 1920x1080 --frames 60 \
    --out "$res/stress-inside.png" --json "$res/stress-inside-render.json" >"$res/stress-inside-render.txt" 2>&1
fi
tar czf "${OUT:-/tmp/out}/$part.tgz" -C "$res" .
