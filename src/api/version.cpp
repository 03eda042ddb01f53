#include "crowdgpu/version.h"

#define CROWDGPU_STRINGIFY2(x) #x
#define CROWDGPU_STRINGIFY(x) CROWDGPU_STRINGIFY2(x)

unsigned crowdgpu_version(void) { return CROWDGPU_VERSION; }

const char* crowdgpu_version_string(void) {
    return CROWDGPU_STRINGIFY(CROWDGPU_VERSION_MAJOR) "." CROWDGPU_STRINGIFY(CROWDGPU_VERSION_MINOR) "." CROWDGPU_STRINGIFY(
        CROWDGPU_VERSION_PATCH);
}
