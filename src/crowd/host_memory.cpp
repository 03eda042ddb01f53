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
    // Crowd: character, agent, plan and its record, changed flags and lists, cursor offset, 6 key cursors a joint.
    const std::uint64_t crowdState = sizeof(Character) + sizeof(Agent) + sizeof(Segment) + sizeof(gpu::MotionRecord) + 1 + 4 + 8 +
                                     6 * sizeof(std::uint16_t) * joints;
    const std::uint64_t renderer = sizeof(gpu::CharacterRecord) + 2 * sizeof(std::uint32_t);
    const std::uint64_t palettes = cpuPalettes ? joints * sizeof(gpu::BoneRows) : 0;
    return characters * (2 * crowdState + renderer + palettes);
}

std::uint64_t availableHostBytes() {
    std::ifstream meminfo("/proc/meminfo");
    std::string line;
    while (std::getline(meminfo, line)) {
        std::istringstream fields(line);
        std::string key;
        std::uint64_t kilobytes = 0;
        if (fields >> key >> kilobytes && key == "MemAvailable:") return kilobytes * 1024;
    }
    const long pages = ::sysconf(_SC_AVPHYS_PAGES), pageSize = ::sysconf(_SC_PAGESIZE);
    return pages > 0 && pageSize > 0 ? static_cast<std::uint64_t>(pages) * static_cast<std::uint64_t>(pageSize) : 0;
}

}  // namespace crowd
