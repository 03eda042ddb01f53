#!/usr/bin/env bash
# Instructions of the CPU palettes, counted by callgrind inside Crowd::computePalettes (4 calls: a
# warm-up and 3 runs, one thread, 1,024 milling soldiers): builds palette_instructions.cpp against each
# CMake build folder given (each a configured, built tree of the commit measured) and runs it.
#   bash bench/results/lavapipe-2026-11-24-simd/instructions.sh build-scalar-src/build build
# (build-scalar-src: `git archive 85a5d23`, configured and built as the README says)
set -euo pipefail
here=$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)
for build in "$@"; do
  build=$(cd "$build" && pwd)
  src=$(sed -n 's/^CMAKE_HOME_DIRECTORY:INTERNAL=//p' "$build/CMakeCache.txt")
  exe=$(mktemp /tmp/palette_instructions.XXXXXX)
  c++ -O3 -DNDEBUG -std=c++20 -I"$src/src/programs" -I"$src/include" "$here/palette_instructions.cpp" -o "$exe" \
    "$build/libcrowd_app.a" "$build/libcrowdgpu-renderer.a" "$build/libcrowdgpu-core.a" \
    -ltinygltf -lmeshoptimizer -lvulkan -lstb
  echo "== $build"
  valgrind --tool=callgrind --callgrind-out-file="$exe.callgrind" --toggle-collect='crowdgpu::Crowd::computePalettes*' \
    "$exe" 1024 3 2>&1 | grep -E "joints|Collected"
  rm -f "$exe" "$exe.callgrind"
done
