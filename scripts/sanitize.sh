#!/usr/bin/env bash
# Builds the programs and the test suite with AddressSanitizer and UndefinedBehaviorSanitizer (gcc,
# -O1, asserts on) in their own build directory and runs the whole suite there. Every test and every
# program a test starts (crowd-render, crowd-bench, crowd-view) runs instrumented; any sanitizer
# report fails the run, also one from a program whose failure a test expected (reports go to files,
# which the script checks, and exit with status 86, which no program uses).
#
# usage: scripts/sanitize.sh [CTEST ARGS...]     e.g. scripts/sanitize.sh -R Gltf
#   SANITIZE_BUILD_DIR  build directory (default build-sanitize; the normal build/ is left alone)
#
# About 7 minutes to build from scratch and half a minute to run on 2 cores. Leaks are checked too;
# scripts/lsan.supp lists those of the Vulkan driver, loader, validation layer and X libraries.
set -euo pipefail

root=$(cd "$(dirname "$0")/.." && pwd)
build=${SANITIZE_BUILD_DIR:-$root/build-sanitize}
flags="-O1 -fsanitize=address,undefined -fno-sanitize-recover=all -fno-omit-frame-pointer"

cmake -S "$root" -B "$build" -DCMAKE_BUILD_TYPE=Debug -DCMAKE_CXX_FLAGS="$flags" \
  -DCMAKE_EXE_LINKER_FLAGS="-fsanitize=address,undefined" >/dev/null
cmake --build "$build" -j"$(nproc)"

# The Vulkan loader unloads the driver and the validation layer when an instance is destroyed, before
# LeakSanitizer looks at exit: their leaks would show as "<unknown module>" and escape the suppressions.
# A dlclose that keeps every library loaded lets the reports name them.
keep_loaded=$build/keep-libraries-loaded.so
echo 'int dlclose(void* handle) { (void)handle; return 0; }' | gcc -shared -fPIC -x c -o "$keep_loaded" -

reports=$build/sanitizer-reports
rm -rf "$reports" && mkdir -p "$reports"
common="exitcode=86:log_path=$reports/report:print_stacktrace=1"
export ASAN_OPTIONS="$common:detect_leaks=1:halt_on_error=1:detect_stack_use_after_return=0:verify_asan_link_order=0"
export UBSAN_OPTIONS="$common:halt_on_error=1"
export LSAN_OPTIONS="suppressions=$root/scripts/lsan.supp:print_suppressions=0"
export LD_PRELOAD="$keep_loaded${LD_PRELOAD:+:$LD_PRELOAD}"

status=0
ctest --test-dir "$build" -j"$(nproc)" --output-on-failure "$@" || status=$?
if compgen -G "$reports/report*" >/dev/null; then
  echo "sanitize.sh: sanitizer reports:" >&2
  for report in "$reports"/report*; do
    echo "== $report" >&2
    head -n 60 "$report" >&2
  done
  exit 1
fi
if (( status != 0 )); then
  echo "sanitize.sh: tests failed (exit $status) without a sanitizer report" >&2
  exit 1
fi
echo "sanitize.sh: no sanitizer reports, all tests passed"
