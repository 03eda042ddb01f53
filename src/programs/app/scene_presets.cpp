#include "app/scene_presets.h"

#include "app/error.h"

namespace app {

std::vector<ScenePreset> scenePresets() {
    using app::CameraPath;
    using crowdgpu::Culling;
    return {
        {"default", "1,024 soldiers on a grid, seen whole (the default without --scene)", "soldier", 1024, true,
         Culling::Gpu, CameraPath::Framed},
        {"paper-fig3", "the paper's Fig. 3: 1,024 soldiers, no LOD, no culling, orbiting camera", "soldier", 1024,
         false, Culling::Off, CameraPath::Orbit},
        {"paper-fig4", "the paper's Fig. 4: 10,240 soldiers, 3 LODs and frustum culling, flying over", "soldier",
         10240, true, Culling::Gpu, CameraPath::FlyOver},
        {"paper-fig5", "the paper's Fig. 5: 5,120 horses, 3 LODs and frustum culling, flying over", "horse", 5120,
         true, Culling::Gpu, CameraPath::FlyOver},
        {"mixed", "4,096 soldiers and horses (3:1) in one crowd, flying over", "soldier:3,horse:1", 4096, true,
         Culling::Gpu, CameraPath::FlyOver},
        {"stress", "100,000 soldiers (--count N for more), from high above down into the crowd", "soldier", 100000,
         true, Culling::Gpu, CameraPath::Descend},
        {"march", "400 soldiers in formation marching in step, turning about and halting, orbiting camera",
         "soldier", 400, true, Culling::Gpu, CameraPath::Orbit, crowdgpu::Behaviour::March},
        {"mill", "4,096 soldiers and horses (3:1) milling: walking, running, stopping, flying over",
         "soldier:3,horse:1", 4096, true, Culling::Gpu, CameraPath::FlyOver, crowdgpu::Behaviour::Mill},
        {"cavalry",
         "1,024 riders and foot soldiers (3:1) in a column marching in step, turning about and halting, orbiting "
         "camera",
         "cavalry:3,soldier:1", 1024, true, Culling::Gpu, CameraPath::Orbit, crowdgpu::Behaviour::March, 4.0f},
    };
}

const ScenePreset& findScenePreset(const std::string& name) {
    static const std::vector<ScenePreset> presets = scenePresets();
    std::string names;
    for (const ScenePreset& p : presets) {
        if (p.name == name) return p;
        names += (names.empty() ? "" : ", ") + p.name;
    }
    throw app::Error("--scene: unknown scene '" + name + "' (" + names + ")");
}

}  // namespace app
