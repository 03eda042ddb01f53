// Thin glue: the single translation unit that compiles Debian's header-only stb_image_write.
#define STB_IMAGE_WRITE_IMPLEMENTATION
#include <stb/stb_image_write.h>
