/* crowdgpu: real-time GPU skinning of large crowds on Vulkan (a library; C and C++).
 *
 * The version of the headers, and of the library linked (they should match: compare
 * CROWDGPU_VERSION with crowdgpu_version() at start-up if the library is loaded at run time). */
#ifndef CROWDGPU_VERSION_H
#define CROWDGPU_VERSION_H

#define CROWDGPU_VERSION_MAJOR 1
#define CROWDGPU_VERSION_MINOR 0
#define CROWDGPU_VERSION_PATCH 0
/* major * 10000 + minor * 100 + patch: 10000 is 1.0.0. */
#define CROWDGPU_VERSION (CROWDGPU_VERSION_MAJOR * 10000 + CROWDGPU_VERSION_MINOR * 100 + CROWDGPU_VERSION_PATCH)

#ifdef __cplusplus
extern "C" {
#endif

/* The version the library was built as, in CROWDGPU_VERSION's form. */
unsigned crowdgpu_version(void);
/* The same as text: "1.0.0". */
const char* crowdgpu_version_string(void);

#ifdef __cplusplus
}
#endif

#endif
