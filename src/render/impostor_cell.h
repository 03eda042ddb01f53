#pragma once
// Which atlas cell an impostor shows and the view each cell was captured from: the C++ twin of
// shaders/impostor_cell.glsl.inc, used by the bake (capture directions) and by the tests (the cell
// the GPU must pick).
//
// Views cover the upper hemisphere: azimuth about +y, measured from +z towards +x, in `azimuths`
// equal steps from 0 (the nearest is shown); elevation above the horizon in `elevations` equal bands
// of 90 / elevations degrees, captured at each band's middle (the band holding the direction is
// shown). Frame k of a clip is captured at phase k / frames, the nearest frame is shown (phases
// wrap). Cell = first + ((clip x frames + frame) x elevations + elevation) x azimuths + azimuth.
//
// Drawn, an impostor blends eight cells (impostorBlend): the two azimuths either side of the direction,
// the two elevation bands either side of it and the two frames either side of the phase, weighted by
// how near each is, so turning, a rising camera or walking changes the picture smoothly; the nearest
// of them (the largest weight) is impostorCell's.
#include <array>
#include <cstdint>

#include <glm/glm.hpp>

#include "gpu_types.h"

namespace render {

// Azimuth (radians, [0, 2 pi)) and elevation (radians, [0, pi / 2]) of a unit direction.
glm::vec2 impostorAngles(const glm::vec3& towardsCamera);

// The cell for a clip, a phase in cycles ([0, 1)) and the unit direction from the character towards
// the eye in the model's own frame.
std::uint32_t impostorCell(const gpu::ImpostorModel& model, std::uint32_t clip, float phase,
                           const glm::vec3& towardsCamera);

// The two elevation bands an elevation (radians) blends, weighted by where it lies between the bands'
// centres (each band is captured at its middle) and clamped below the lowest band's centre and above
// the highest's: `lower` (e0) and, when `share` > 0, e0 + 1 with that share. `band` is the band holding
// the elevation (impostorCell's), always the nearer of the two (e0 when the share is under half).
struct ImpostorBands {
    std::uint32_t band = 0, lower = 0;
    float share = 0.0f;
};
ImpostorBands impostorBands(float elevation, std::uint32_t bands);

// The cells an impostor blends and their weights: cells[i] is at azimuth step a0 + (i & 1) and frame
// f0 + (i >> 1) (both wrapping) in band e0, where a0 and f0 are the steps at or below the direction and
// the phase; the same four in band e0 + 1 are cells[i] + bandStep (0 where the band's share is 0).
// weights.x is the share of the next azimuth, weights.y of the next frame, weights.z of band e0 + 1
// (trilinear). cell(i) and weight(i) name all eight, i & 4 the upper band.
struct ImpostorBlend {
    std::array<std::uint32_t, 4> cells{};
    std::uint32_t bandStep = 0;
    glm::vec3 weights{0.0f};
    std::uint32_t cell(std::uint32_t i) const { return cells[i & 3u] + ((i & 4u) ? bandStep : 0u); }
    float weight(std::uint32_t i) const {
        return ((i & 1u) ? weights.x : 1.0f - weights.x) * ((i & 2u) ? weights.y : 1.0f - weights.y) *
               ((i & 4u) ? weights.z : 1.0f - weights.z);
    }
};
ImpostorBlend impostorBlend(const gpu::ImpostorModel& model, std::uint32_t clip, float phase,
                            const glm::vec3& towardsCamera);

// The direction (towards the viewer) cell view (azimuth index, elevation index) was captured from.
glm::vec3 impostorViewDirection(const gpu::ImpostorModel& model, std::uint32_t azimuth, std::uint32_t elevation);

// The image plane of a view: right horizontal (from the azimuth), up completing the frame.
void impostorBasis(const glm::vec3& towardsCamera, glm::vec3& right, glm::vec3& up);

}  // namespace render
