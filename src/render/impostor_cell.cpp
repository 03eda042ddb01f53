#include "render/impostor_cell.h"

#include <algorithm>
#include <cmath>

namespace render {

namespace {
constexpr float kPi = 3.14159265358979f;
}

glm::vec2 impostorAngles(const glm::vec3& d) {
    float azimuth = d.x * d.x + d.z * d.z > 1e-12f ? std::atan2(d.x, d.z) : 0.0f;
    if (azimuth < 0.0f) azimuth += 2.0f * kPi;
    return {azimuth, std::asin(std::clamp(d.y, 0.0f, 1.0f))};
}

std::uint32_t impostorCell(const gpu::ImpostorModel& m, std::uint32_t clip, float phase, const glm::vec3& towardsCamera) {
    const glm::vec2 angles = impostorAngles(towardsCamera);
    const std::uint32_t azimuth =
        static_cast<std::uint32_t>(std::floor(angles.x / (2.0f * kPi) * static_cast<float>(m.views.x) + 0.5f)) % m.views.x;
    const std::uint32_t elevation = impostorBands(angles.y, m.views.y).band;
    const std::uint32_t frame =
        static_cast<std::uint32_t>(std::floor(phase * static_cast<float>(m.cells.z) + 0.5f)) % m.cells.z;
    const std::uint32_t pose = std::min(clip, m.cells.y - 1u) * m.cells.z + frame;
    return m.cells.x + (pose * m.views.y + elevation) * m.views.x + azimuth;
}

ImpostorBands impostorBands(float elevation, std::uint32_t bands) {
    const float e = elevation / (0.5f * kPi) * static_cast<float>(bands);
    const std::uint32_t band = std::min(static_cast<std::uint32_t>(e), bands - 1u);
    const float along = e - static_cast<float>(band);  // 0 at the band's lower edge, 0.5 at its centre
    if (along < 0.5f) return band == 0u ? ImpostorBands{band, band, 0.0f} : ImpostorBands{band, band - 1u, along + 0.5f};
    return band + 1u == bands ? ImpostorBands{band, band, 0.0f} : ImpostorBands{band, band, along - 0.5f};
}

ImpostorBlend impostorBlend(const gpu::ImpostorModel& m, std::uint32_t clip, float phase, const glm::vec3& towardsCamera) {
    const glm::vec2 angles = impostorAngles(towardsCamera);
    const float a = angles.x / (2.0f * kPi) * static_cast<float>(m.views.x);
    const float f = phase * static_cast<float>(m.cells.z);
    const std::uint32_t a0 = static_cast<std::uint32_t>(std::floor(a)) % m.views.x, a1 = (a0 + 1u) % m.views.x;
    const std::uint32_t f0 = static_cast<std::uint32_t>(std::floor(f)) % m.cells.z, f1 = (f0 + 1u) % m.cells.z;
    const ImpostorBands bands = impostorBands(angles.y, m.views.y);
    const std::uint32_t firstPose = std::min(clip, m.cells.y - 1u) * m.cells.z;
    auto cell = [&](std::uint32_t frame, std::uint32_t azimuth) {
        return m.cells.x + ((firstPose + frame) * m.views.y + bands.lower) * m.views.x + azimuth;
    };
    ImpostorBlend blend;
    blend.cells = {cell(f0, a0), cell(f0, a1), cell(f1, a0), cell(f1, a1)};
    blend.bandStep = bands.share > 0.0f ? m.views.x : 0u;
    blend.weights = {a - std::floor(a), f - std::floor(f), bands.share};
    return blend;
}

glm::vec3 impostorViewDirection(const gpu::ImpostorModel& m, std::uint32_t azimuth, std::uint32_t elevation) {
    const float a = 2.0f * kPi * static_cast<float>(azimuth) / static_cast<float>(m.views.x);
    const float e = 0.5f * kPi * (static_cast<float>(elevation) + 0.5f) / static_cast<float>(m.views.y);
    return {std::sin(a) * std::cos(e), std::sin(e), std::cos(a) * std::cos(e)};
}

void impostorBasis(const glm::vec3& towardsCamera, glm::vec3& right, glm::vec3& up) {
    const float azimuth = impostorAngles(towardsCamera).x;
    right = glm::vec3(std::cos(azimuth), 0.0f, -std::sin(azimuth));
    up = glm::normalize(glm::cross(towardsCamera, right));
}

}  // namespace render
