# Sourced by the bench/run_*.sh scripts that run on a lent GPU machine: what each does before its own
# measurements. Functions only; nothing runs on sourcing.

# The Vulkan loader packages carried in .gl/ (a lent machine has a driver but no loader).
install_vulkan_loader() {
  [[ -d .gl ]] || return 0
  for f in .gl/*.deb; do dpkg -x "$f" /; done
  ldconfig
}

# Finds the device with the caller's probe() (a one-frame run naming "${device_flag[@]}"); when the
# NVIDIA driver is not among the loader's, names its ICD and probes again. Exits naming SCRIPT when
# no device matches $device. Then records nvidia-smi's view in $res/nvidia-smi.txt (and prints it
# unless QUIET is given).
find_device() {  # SCRIPT [QUIET]
  if ! probe && [[ -n $device ]]; then
    export VK_DRIVER_FILES=/usr/local/nvidia/share/vulkan/icd.d/nvidia_icd.json
    probe || { cat "$res/probe.txt"; echo "$1: no device named like '$device'"; exit 1; }
  fi
  nvidia-smi --query-gpu=name,driver_version,clocks.sm,clocks.mem --format=csv >"$res/nvidia-smi.txt" 2>&1
  [[ -n ${2:-} ]] || cat "$res/nvidia-smi.txt"
}

# The start every run shares, once the script has set device, bin, res and out: a fresh $res and $out,
# the loader, $bin on the library path, device_flag, and the device found (find_device SCRIPT [QUIET]).
# The script's own probe() when it defined one, else crowd-render's one-frame run.
begin_run() {  # SCRIPT [QUIET]
  rm -rf "$res"
  mkdir -p "$res" "$out"
  install_vulkan_loader
  export LD_LIBRARY_PATH=$bin${LD_LIBRARY_PATH:+:$LD_LIBRARY_PATH}
  device_flag=()
  [[ -n $device ]] && device_flag=(--device "$device")
  declare -F probe >/dev/null ||
    probe() { "$bin/crowd-render" "${device_flag[@]}" --count 1 --frames 1 --size 64x64 --out "$res/probe.png" >"$res/probe.txt" 2>&1; }
  find_device "$@"
}

# run NAME PROGRAM ARGS...: its output in $res/NAME.txt, its command in $res/commands.txt; a failure
# is counted in $failures and its last lines printed. Returns the program's status.
run() {
  local name=$1; shift
  echo "$*" >>"$res/commands.txt"
  echo "== $name"
  "$@" >"$res/$name.txt" 2>&1
  local status=$?
  if [[ $status != 0 ]]; then
    failures=$((failures + 1))
    echo "   failed (exit $status):"; tail -3 "$res/$name.txt"
  fi
  return $status
}

# The value of column $2 in the first data row of the CSV file $1 (quoted fields may hold commas).
csv_value() {
  awk -v want="$2" '
    function fields(line, out,   n, i, c, field, quoted) {
      n = 0; field = ""; quoted = 0
      for (i = 1; i <= length(line); i++) {
        c = substr(line, i, 1)
        if (c == "\"") quoted = !quoted
        else if (c == "," && !quoted) { out[++n] = field; field = "" }
        else field = field c
      }
      out[++n] = field
      return n
    }
    NR == 1 { n = fields($0, head); for (i = 1; i <= n; i++) if (head[i] == want) column = i; next }
    NR == 2 { fields($0, row); if (column) print row[column]; exit }' "$1" 2>/dev/null
}

# The program $2 of build $1, for the scripts that compare two builds: before's in $bin, after's in
# $after.
exe() { [[ $1 == before ]] && echo "$bin/$2" || echo "$after/$2"; }
