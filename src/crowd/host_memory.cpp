#include "crowd/host_memory.h"

#include <algorithm>
#include <fstream>
#include <sstream>
#include <string>
#include <unistd.h>

#include "crowd/behaviours.h"
#include "crowd/crowd.h"
#include "gpu_types.h"

namespace crowd {

std::uint64_t estimateHostBytes(std::span<const model::SkinnedModel* const> models, std::uint64_t characters,
                                bool cpuPalettes) {
    std::uint64_t joints = 1;
    for (const model::SkinnedModel* m : models) joints = std::max<std::uint64_t>(joints, m->skeleton.jointCount());
    // Crowd: character, agent, plan, the plan before it and from when it holds, the plan's record,
    // changed flags and lists, cursor offset, 6 key cursors a joint.
    const std::uint64_t crowdState = sizeof(Character) + sizeof(Agent) + 2 * sizeof(Segment) + sizeof(double) +
                                     sizeof(gpu::MotionRecord) + 1 + 4 + 8 +
                                     6 * sizeof(std::uint16_t) * joints;
    const std::uint64_t renderer = sizeof(gpu::CharacterRecord) + 2 * sizeof(std::uint32_t);
    const std::uint64_t palettes = cpuPalettes ? joints * sizeof(gpu::BoneRows) : 0;
    return characters * (2 * crowdState + renderer + palettes);
}

}  // namespace crowd
