#pragma once
// Camera paths of the scenes: frame N of a scene is deterministic (time = N / 60 s), and the paths
// go through or over the crowd so that culling and levels of detail change over time.
#include <string>


#include "app/camera.h"

namespace app {

enum class CameraPath {
    Framed,   // still, a three-quarter view framing the whole crowd
    Orbit,    // circles the crowd at the framed distance, once every 40 s
    FlyOver,  // flies a circle low over the crowd every 40 s, looking ahead and down
    Descend,  // from high over the whole crowd down to eye level inside it and back up, every 40 s
};
const char* cameraPathName(CameraPath path);

// `seconds` is scene time, a double: the paths repeat, so only its place within a period matters.
Camera cameraOnPath(CameraPath path, const CrowdShape& crowd, float aspect, double seconds);

}  // namespace app
