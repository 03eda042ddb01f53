#pragma once
// The scenes every program knows by name (--scene): the paper's Fig. 3, 4 and 5, a mixed crowd, and
// a stress test, and two living crowds (march, mill); each sets the crowd, what it does, culling, LOD
// and a camera path. Flags given beside --scene
// override its settings.
#include <cstdint>
#include <string>
#include <vector>

#include "crowd/behaviours.h"
#include "render/camera_path.h"
#include "render/cull_pass.h"

namespace app {

struct ScenePreset {
    std::string name;
    std::string description;
    std::string models;  // --model list: NAME[:WEIGHT],...
    std::uint32_t count;
    bool lod;
    render::CullMode cull;
    render::CameraPath camera;
    crowd::Behaviour behaviour = crowd::Behaviour::InPlace;
};

std::vector<ScenePreset> scenePresets();
// The preset of this name; throws gpu::Error listing the scenes when there is none.
const ScenePreset& findScenePreset(const std::string& name);

}  // namespace app
