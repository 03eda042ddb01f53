#pragma once
// The scenes every program knows by name (--scene): the paper's Fig. 3, 4 and 5, a mixed crowd, and
// a stress test, and three living crowds (march, mill, cavalry); each sets the crowd, what it does, culling, LOD
// and a camera path. Flags given beside --scene
// override its settings.
#include <cstdint>
#include <string>
#include <vector>

#include <crowdgpu/crowd.hpp>
#include <crowdgpu/renderer.hpp>

#include "app/camera_path.h"

namespace app {

struct ScenePreset {
    std::string name;
    std::string description;
    std::string models;  // --model list: NAME[:WEIGHT],...
    std::uint32_t count;
    bool lod;
    crowdgpu::Culling cull;
    app::CameraPath camera;
    crowdgpu::Behaviour behaviour = crowdgpu::Behaviour::InPlace;
    float depthRatio = 1.0f;  // the grid's rows over columns: 1 a square, more a column (crowdgpu::GridLayout)
};

std::vector<ScenePreset> scenePresets();
// The preset of this name; throws app::Error listing the scenes when there is none.
const ScenePreset& findScenePreset(const std::string& name);

}  // namespace app
