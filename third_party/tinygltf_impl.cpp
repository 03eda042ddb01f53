// Thin glue for builds that compile tinygltf and stb_image from source: the fuzzer does, so that
// the sanitizers see inside them. The main build links Debian's shared libtinygltf and libstb instead.
#define TINYGLTF_IMPLEMENTATION
#define STB_IMAGE_WRITE_IMPLEMENTATION
#define STB_IMAGE_IMPLEMENTATION
#include <tiny_gltf.h>
