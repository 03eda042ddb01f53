#include "scenes.hpp"

#include <cmath>

namespace {

// Component-wise float arithmetic in the order crowdgpu's programs evaluate it (glm there), so that
// the camera comes out bit for bit the same and the example's frames are the programs' frames.
struct Vec3 {
    float x, y, z;
};
Vec3 operator+(Vec3 a, Vec3 b) { return {a.x + b.x, a.y + b.y, a.z + b.z}; }
Vec3 operator-(Vec3 a, Vec3 b) { return {a.x - b.x, a.y - b.y, a.z - b.z}; }
Vec3 operator*(Vec3 a, float s) { return {a.x * s, a.y * s, a.z * s}; }
Vec3 mix(Vec3 a, Vec3 b, float t) { return a * (1.0f - t) + b * t; }

// What a camera path needs to know of the crowd: where it stands and how tall its characters are.
struct CrowdShape {
    Vec3 center;
    float radius;
    float height;
};

CrowdShape shapeOf(const crowdgpu::Crowd& crowd) {
    float center[3], radius, tallest;
    crowd.bounds(center, radius, tallest);
    return {{center[0], center[1], center[2]}, radius, tallest};
}

constexpr float kPi = 3.14159265358979f;
constexpr float kPathPeriod = 40.0f;      // seconds for a whole camera path (there and back)
constexpr float kProgramsFov = 0.7f;      // the programs' vertical field of view, radians

CameraPose pose(Vec3 eye, Vec3 target, float fov, float nearPlane, float farPlane) {
    return {{eye.x, eye.y, eye.z}, {target.x, target.y, target.z}, fov, nearPlane, farPlane};
}

// The example's own view: three-quarter from above, the whole crowd and the host's boxes in it.
CameraPose threeQuarter(const CrowdShape& crowd) {
    const Vec3 target = crowd.center + Vec3{0.0f, 0.4f * crowd.height, 0.0f};
    const Vec3 eye = crowd.center + Vec3{0.5f * crowd.radius, 1.1f * crowd.radius + crowd.height,
                                         1.8f * crowd.radius + 2.0f * crowd.height};
    return pose(eye, target, 0.8f, 0.1f, 20.0f * crowd.radius);
}

// paper-fig4's path: a circle low over the crowd every 40 s, looking ahead along the flight and down,
// so near characters pass below, far ones stay in view and the ones behind are culled.
CameraPose flyOver(const CrowdShape& crowd, float seconds) {
    const float h = crowd.height;
    const float angle = 2.0f * kPi * seconds / kPathPeriod;
    const float r = 0.55f * crowd.radius;
    const Vec3 ground = crowd.center + Vec3{r * std::cos(angle), 0.0f, r * std::sin(angle)};
    const Vec3 forward{-std::sin(angle), 0.0f, std::cos(angle)};
    const Vec3 eye = ground + Vec3{0.0f, 5.0f * h, 0.0f};
    const Vec3 target = eye + forward * (12.0f * h) - Vec3{0.0f, 4.5f * h, 0.0f};
    return pose(eye, target, kProgramsFov, 0.05f * h, 2.5f * crowd.radius + 20.0f * h);
}

// 0 -> 1 -> 0 over the path's period, eased at both ends.
float pingPong(float seconds) {
    const float u = seconds / kPathPeriod - std::floor(seconds / kPathPeriod);
    const float t = u < 0.5f ? 2.0f * u : 2.0f - 2.0f * u;
    return t * t * (3.0f - 2.0f * t);
}

// stress's path: from over the crowd's near edge looking at its centre, down to eye level a quarter
// of the way in looking across it (reached at 20 s), and back up.
CameraPose descend(const CrowdShape& crowd, float seconds) {
    const float h = crowd.height;
    const float t = pingPong(seconds);
    const Vec3 highEye = crowd.center + Vec3{0.2f, 1.1f, 0.9f} * crowd.radius;
    const Vec3 lowEye = crowd.center + Vec3{0.05f * crowd.radius, 0.95f * h, 0.25f * crowd.radius};
    const Vec3 highTarget = crowd.center;
    const Vec3 lowTarget = crowd.center + Vec3{0.0f, 0.8f * h, -0.5f * crowd.radius};
    return pose(mix(highEye, lowEye, t), mix(highTarget, lowTarget, t), kProgramsFov, 0.05f * h,
                3.0f * crowd.radius + 20.0f * h);
}

}  // namespace

bool parseScene(const std::string& name, Scene& scene) {
    for (Scene s : {Scene::Own, Scene::PaperFig4, Scene::Stress})
        if (name == sceneName(s)) return scene = s, true;
    return false;
}

const char* sceneName(Scene scene) {
    switch (scene) {
        case Scene::Own: return "own";
        case Scene::PaperFig4: return "paper-fig4";
        case Scene::Stress: return "stress";
    }
    return "?";
}

std::uint32_t defaultCount(Scene scene) {
    switch (scene) {
        case Scene::Own: return 64;
        case Scene::PaperFig4: return 10240;
        case Scene::Stress: return 100000;
    }
    return 0;
}

crowdgpu::Crowd makeCrowd(std::uint32_t count) {
    crowdgpu::GridLayout layout;
    layout.count = count;
    return crowdgpu::Crowd::grid({crowdgpu::Model::soldier(1)}, layout);
}

CameraPose cameraAt(Scene scene, const crowdgpu::Crowd& crowd, double sceneSeconds) {
    // The paths repeat every kPathPeriod: only the place within a period matters, kept in a float.
    const float seconds = static_cast<float>(sceneSeconds - std::floor(sceneSeconds / kPathPeriod) * kPathPeriod);
    const CrowdShape shape = shapeOf(crowd);
    switch (scene) {
        case Scene::Own: return threeQuarter(shape);
        case Scene::PaperFig4: return flyOver(shape, seconds);
        case Scene::Stress: return descend(shape, seconds);
    }
    return threeQuarter(shape);
}
