#!/usr/bin/env bash
# Fuzzes the glTF loader with libFuzzer (clang, AddressSanitizer, UndefinedBehaviorSanitizer) for a
# bounded time and fails on any crash, sanitizer report, broken invariant or input slower than 10 s.
#
# usage: scripts/fuzz.sh [SECONDS]     (default 60)
#   FUZZ_BUILD_DIR  build directory (default build-fuzz; separate from the gcc build)
#
# Two phases share the time. Two thirds go to small inputs (at most 16 KiB) grown from the
# hand-made characters in fuzz/seeds (see fuzz/make_seeds.py) and the earlier finds in
# fuzz/regressions: thousands of runs a second, deep into the loader. The last third starts from
# every seed, including the skinned assets in ../shared/assets and assimp-testmodels' glTF files
# when present: real files, but with textures that make each run take milliseconds.
# New interesting inputs go to $FUZZ_BUILD_DIR/corpus-*; a failing input is left in
# $FUZZ_BUILD_DIR/crashes/. Keep each in fuzz/regressions (every run replays them) and turn it into a
# test in tests/test_gltf_bad_input.cpp.
set -euo pipefail

seconds=${1:-60}
if ! [[ $seconds =~ ^[0-9]+$ ]] || (( seconds < 2 )); then
  echo "fuzz.sh: SECONDS must be a whole number of at least 2, got '$seconds'" >&2
  exit 2
fi
root=$(cd "$(dirname "$0")/.." && pwd)
build=${FUZZ_BUILD_DIR:-$root/build-fuzz}
clangxx=$(command -v clang++ || command -v clang++-14 || true)
if [[ -z $clangxx ]]; then
  echo "fuzz.sh: clang++ not found (scripts/setup.sh --tests installs clang and libclang-rt-14-dev)" >&2
  exit 2
fi

cmake -S "$root/fuzz" -B "$build" -DCMAKE_CXX_COMPILER="$clangxx" -DCMAKE_BUILD_TYPE=RelWithDebInfo >/dev/null
cmake --build "$build" -j"$(nproc)"

# libFuzzer reads seed directories flat: gather each phase's glTF files into one directory.
gather() {
  local into=$1
  shift
  rm -rf "$into" && mkdir -p "$into"
  local n=0 file
  while IFS= read -r -d '' file; do
    cp "$file" "$into/$((n++))-$(basename "$file")"
  done < <(find "$@" -type f \( -iname '*.gltf' -o -iname '*.glb' \) -print0)
  echo "$n"
}
small_seeds=("$root/fuzz/seeds" "$root/fuzz/regressions")
all_seeds=("${small_seeds[@]}")
[[ -d $root/../shared/assets ]] && all_seeds+=("$root/../shared/assets")
for dir in /usr/share/assimp/models/glTF2 /usr/share/assimp/models/glTF; do
  [[ -d $dir ]] && all_seeds+=("$dir")
done
mkdir -p "$build/crashes" "$build/corpus-small" "$build/corpus-all"

# fuzz PHASE SECONDS MAX_LEN SEEDS...: one libFuzzer run; -rss_limit_mb: no input may need 2 GiB.
fuzz() {
  local phase=$1 time=$2 max_len=$3
  shift 3
  local seed_dir=$build/seeds-$phase
  local n
  n=$(gather "$seed_dir" "$@")
  echo "fuzz.sh: phase '$phase': $n seed files, ${time}s, inputs up to $max_len bytes"
  ASAN_OPTIONS=${ASAN_OPTIONS:-detect_leaks=1} \
  "$build/gltf_loader_fuzzer" "$build/corpus-$phase" "$seed_dir" \
    -dict="$root/fuzz/gltf.dict" -max_total_time="$time" -timeout=10 -rss_limit_mb=2048 -max_len="$max_len" \
    -artifact_prefix="$build/crashes/" -print_final_stats=1
}

small_time=$(( seconds * 2 / 3 ))
status=0
fuzz small "$small_time" 16384 "${small_seeds[@]}" || status=$?
if (( status == 0 )); then
  fuzz all "$(( seconds - small_time ))" 1048576 "${all_seeds[@]}" || status=$?
fi
if (( status != 0 )); then
  echo "fuzz.sh: the fuzzer found a failure (exit $status); the input is in $build/crashes/" >&2
  exit 1
fi
echo "fuzz.sh: no failures in ${seconds}s"
