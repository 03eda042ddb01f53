#!/usr/bin/env bash
# Soak check: a long run must keep its memory flat. Runs crowd-render for thousands of frames of a
# small crowd (and crowd-view for a minute under a virtual X server, when it is built and Xvfb is
# there), samples each program's resident memory (VmRSS) every second, and says whether it stayed
# flat: after the first quarter of the samples (start-up: pipelines, the driver's first compiles), no
# sample may exceed that quarter's last sample by more than the bound.
#
# usage: scripts/soak.sh [FRAMES] [VIEWER_SECONDS]     (defaults 5000 and 60; 0 skips that program)
#   SOAK_BUILD_DIR   where the programs are (default build)
#   SOAK_BOUND_MB    allowed growth in MB (default 24)
#   SOAK_ARGS        extra flags for both programs (e.g. "--method compute --impostors on")
#
# Exit status 0 when every program stayed within the bound, 1 when one grew past it or failed.
set -euo pipefail

root=$(cd "$(dirname "$0")/.." && pwd)
build=${SOAK_BUILD_DIR:-$root/build}
bound_mb=${SOAK_BOUND_MB:-24}
frames=${1:-5000}
viewer_seconds=${2:-60}
crowd="--count 16 --size 64x64 ${SOAK_ARGS:-}"
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT

rss_kb() { awk '/^VmRSS:/ { print $2 }' "/proc/$1/status" 2>/dev/null || true; }

# Samples the VmRSS of process $1 every second until it exits or $2 seconds have passed (then it is
# stopped); prints the samples and the verdict, and returns 1 when it grew past the bound.
watch_process() {
  local pid=$1 limit=$2 name=$3 samples=() t=0 kb
  while kill -0 "$pid" 2>/dev/null && (( t < limit )); do
    kb=$(rss_kb "$pid")
    [[ -n $kb ]] && samples+=("$kb") && printf '%s  t=%3ds  RSS %7.1f MB\n' "$name" "$t" "$(awk -v k="$kb" 'BEGIN { printf "%.1f", k / 1024 }')"
    sleep 1
    t=$((t + 1))
  done
  if kill -0 "$pid" 2>/dev/null; then kill "$pid" 2>/dev/null || true; fi
  wait "$pid" 2>/dev/null || true
  verdict "$name" "${samples[@]}"
}

verdict() {
  local name=$1; shift
  local samples=("$@") n=$#
  if (( n < 4 )); then
    echo "$name: only $n samples (a run shorter than 4 s): raise FRAMES" >&2
    return 1
  fi
  local base=${samples[$((n / 4))]} peak=0 i
  for (( i = n / 4; i < n; i++ )); do (( samples[i] > peak )) && peak=${samples[i]}; done
  local growth_mb
  growth_mb=$(awk -v p="$peak" -v b="$base" 'BEGIN { printf "%.1f", (p - b) / 1024 }')
  if (( peak - base > bound_mb * 1024 )); then
    echo "$name: NOT FLAT: grew $growth_mb MB after start-up ($((base / 1024)) -> $((peak / 1024)) MB; bound $bound_mb MB)"
    return 1
  fi
  echo "$name: flat: grew $growth_mb MB after start-up ($((base / 1024)) -> $((peak / 1024)) MB; bound $bound_mb MB)"
}

status=0
if (( frames > 0 )); then
  # shellcheck disable=SC2086  # $crowd is a list of flags
  "$build/crowd-render" $crowd --frames "$frames" --out "$work/soak.png" >"$work/render.log" 2>&1 &
  watch_process $! 100000 "crowd-render ($frames frames)" || status=1
  [[ -s $work/soak.png ]] || { echo "crowd-render failed:" >&2; cat "$work/render.log" >&2; status=1; }
fi

if (( viewer_seconds > 0 )); then
  if [[ ! -x $build/crowd-view ]]; then
    echo "crowd-view: not built, skipped"
  elif ! command -v Xvfb >/dev/null; then
    echo "crowd-view: Xvfb not found (apt-get install xvfb), skipped"
  else
    # Xvfb picks a free display and writes its number to fd 3.
    Xvfb -displayfd 3 -screen 0 640x480x24 3>"$work/display" >/dev/null 2>&1 &
    xvfb=$!
    for _ in $(seq 50); do [[ -s $work/display ]] && break; sleep 0.1; done
    # shellcheck disable=SC2086
    DISPLAY=:$(cat "$work/display") "$build/crowd-view" $crowd --vsync off >"$work/view.log" 2>&1 &
    watch_process $! "$viewer_seconds" "crowd-view (${viewer_seconds} s)" || status=1
    kill "$xvfb" 2>/dev/null || true
    wait "$xvfb" 2>/dev/null || true
  fi
fi
exit $status
