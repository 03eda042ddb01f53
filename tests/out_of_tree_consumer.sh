#!/bin/bash
# The library as a user gets it: install the build tree into a temporary prefix, build
# examples/embed_headless against it with find_package(crowdgpu), run it under the validation layer
# (synchronization validation on; any message fails), check its images; then compile and link a C
# program against the same prefix with pkg-config's flags alone.
#   tests/out_of_tree_consumer.sh <build dir> <source dir>
set -euo pipefail
build=$(realpath "$1")
source=$(realpath "$2")
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT

echo "== install into $tmp/prefix"
cmake --install "$build" --prefix "$tmp/prefix" >/dev/null

echo "== configure and build the example against it"
cmake -S "$source/examples/embed_headless" -B "$tmp/example" -DCMAKE_PREFIX_PATH="$tmp/prefix" >"$tmp/configure.log" \
  || { cat "$tmp/configure.log"; exit 1; }
cmake --build "$tmp/example" -j2 >"$tmp/build.log" || { cat "$tmp/build.log"; exit 1; }

echo "== run it with validation"
mkdir "$tmp/out"
CROWDGPU_VALIDATION=1 "$tmp/example/embed_headless" "$tmp/out" 256x192 3

echo "== check its images"
python3 - "$tmp/out/crowd.ppm" "$tmp/out/ids.pgm" <<'EOF'
import sys

def read_pnm(path):
    data = open(path, "rb").read()
    fields, i = [], 0
    while len(fields) < 4:
        while data[i:i + 1].isspace():
            i += 1
        j = i
        while not data[j:j + 1].isspace():
            j += 1
        fields.append(data[i:j])
        i = j
    return fields[0], int(fields[1]), int(fields[2]), data[i + 1:]

kind, w, h, rgb = read_pnm(sys.argv[1])
kind2, w2, h2, raw = read_pnm(sys.argv[2])
assert kind == b"P6" and kind2 == b"P5" and (w, h) == (w2, h2), "crowd.ppm must be P6 and ids.pgm P5 of one size"
pixels = [tuple(rgb[3 * i:3 * i + 3]) for i in range(w * h)]
ids = [(raw[2 * i] << 8) | raw[2 * i + 1] for i in range(w * h)]

# The example's own colours as its sRGB target stores them: sky (clear), ground, box faces (orange).
def near(p, q, tolerance=3):
    return all(abs(a - b) <= tolerance for a, b in zip(p, q))
sky, ground = (196, 218, 243), (149, 149, 144)
def is_box(p):
    return p[0] >= 180 and 95 <= p[1] <= 150 and p[2] <= 50 and p[0] - p[1] >= 70
def is_background(p):
    return near(p, sky) or near(p, ground) or is_box(p)

crowd = [i for i in range(w * h) if ids[i]]
distinct = len(set(ids[i] for i in crowd))
crowd_coloured = sum(1 for i in crowd if not is_background(pixels[i]))
boxes = [i for i in range(w * h) if is_box(pixels[i])]
boxes_without_id = sum(1 for i in boxes if ids[i] == 0)
others = [i for i in range(w * h) if not ids[i]]
others_background = sum(1 for i in others if is_background(pixels[i]))
print(f"{distinct} distinct ids, {len(crowd)} crowd pixels ({crowd_coloured} crowd-coloured), "
      f"{len(boxes)} box pixels ({boxes_without_id} without an id), "
      f"{others_background} of {len(others)} pixels without an id are sky, ground or box")
ok = True
def check(condition, message):
    global ok
    if not condition:
        print("FAIL:", message)
        ok = False
check(distinct >= 30, "fewer than 30 distinct characters in the ID image")
check(max(ids) <= 64, "an id over the crowd's 64 characters")
check(crowd_coloured >= 0.98 * len(crowd), "ID pixels whose colour is sky, ground or box")
check(len(boxes) >= 0.01 * w * h, "too few box-coloured pixels")
check(boxes_without_id >= 0.99 * len(boxes), "box pixels with a character id")
check(others_background >= 0.99 * len(others), "character-coloured pixels without an id")
sys.exit(0 if ok else 1)
EOF

echo "== pkg-config: a C program against the prefix"
export PKG_CONFIG_PATH="$tmp/prefix/lib/pkgconfig"
flags=$(pkg-config --cflags --libs crowdgpu)
echo "pkg-config --cflags --libs crowdgpu: $flags"
cat >"$tmp/version.c" <<'EOF'
#include <stdio.h>
#include <string.h>
#include <crowdgpu/crowdgpu.h>

int main(void) {
    /* Referencing the renderer pulls every archive member and dependency into the link. */
    crowdgpu_result (*volatile create)(const crowdgpu_device*, crowdgpu_crowd, const crowdgpu_renderer_settings*,
                                       crowdgpu_renderer*) = crowdgpu_renderer_create;
    crowdgpu_model model = NULL;
    if (!create || crowdgpu_model_soldier(1, &model) != CROWDGPU_OK) return 1;
    printf("crowdgpu %s (%u), soldier with %u clips\n", crowdgpu_version_string(), crowdgpu_version(),
           crowdgpu_model_clip_count(model));
    crowdgpu_model_destroy(model);
    return crowdgpu_version() == CROWDGPU_VERSION && strlen(crowdgpu_last_error()) == 0 ? 0 : 1;
}
EOF
# shellcheck disable=SC2086  # the flags are words
cc -std=c11 -Wall -Werror "$tmp/version.c" -o "$tmp/version" $flags
"$tmp/version"
echo "out-of-tree consumer: OK"
