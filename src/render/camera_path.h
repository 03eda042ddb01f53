#pragma once
// Camera paths of the scenes: frame N of a scene is deterministic (time = N / 60 s), and the paths
// go through or over the crowd so that culling and levels of detail change over time.
#include <string>

#include <glm/glm.hpp>

#include "render/camera.h"

namespace render {

enum class CameraPath {
    Framed,   // still, a three-quarter view framing the whole crowd
    Orbit,    // circles the crowd at the framed distance, once every 40 s
    FlyOver,  // flies a circle low over the crowd every 40 s, looking ahead and down
    Descend,  // from high over the whole crowd down to eye level inside it and back up, every 40 s
};
const char* cameraPathName(CameraPath path);

// What a path needs to know of the crowd: where it stands and how big its characters are.
struct CrowdShape {
    glm::vec3 center{0.0f};
    float radius = 1.0f;
    float characterHeight = 1.0f;
};

// `seconds` is scene time, a double: the paths repeat, so only its place within a period matters.
Camera cameraOnPath(CameraPath path, const CrowdShape& crowd, float aspect, double seconds);

}  // namespace render
