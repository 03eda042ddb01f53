#!/usr/bin/env bash
# Builds libcrowdgpu-dev's Debian package with CPack, unpacks it into a temporary root (dpkg -x: no
# root rights, the system untouched), and builds and runs examples/embed_headless against that root
# as a user of the package would (find_package and pkg-config).
#
# usage: scripts/check_deb.sh [BUILD_DIR]     (default build; configured and built already)
# `cpack` runs the build's preinstall target, so everything the build has is brought up to date.
# To check the package installed for real:  sudo dpkg -i BUILD_DIR/libcrowdgpu-dev_*.deb, then
#   cmake -S examples/embed_headless -B /tmp/embed-usr   (finds /usr/lib/cmake/crowdgpu).
set -euo pipefail
source=$(realpath "$(dirname "$0")/..")
build=$(realpath "${1:-$source/build}")

(cd "$build" && cpack -G DEB)
version=$(sed -n 's/^#define CROWDGPU_VERSION_\(MAJOR\|MINOR\|PATCH\) \([0-9]*\)$/\2/p' \
  "$source/include/crowdgpu/version.h" | paste -sd.)
deb=$(ls "$build"/libcrowdgpu-dev_"${version}"_*.deb)
echo "== $deb"
dpkg-deb --field "$deb" Package Version Architecture Depends
dpkg-deb --contents "$deb" | awk '{print $6}'

root=$(mktemp -d)
trap 'rm -rf "$root"' EXIT
dpkg -x "$deb" "$root"
echo "== examples/embed_headless against $root/usr"
cmake -S "$source/examples/embed_headless" -B "$root/example" -DCMAKE_PREFIX_PATH="$root/usr" >/dev/null
cmake --build "$root/example" -j2 >/dev/null
mkdir "$root/out"
CROWDGPU_VALIDATION=1 "$root/example/embed_headless" "$root/out" 256x192 3
export PKG_CONFIG_PATH=$root/usr/lib/pkgconfig
echo "pkg-config: crowdgpu $(pkg-config --modversion crowdgpu): $(pkg-config --cflags --libs crowdgpu)"
echo "check_deb: OK"
