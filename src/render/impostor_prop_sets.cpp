#include "render/impostor_prop_sets.h"

#include <algorithm>
#include <bit>
#include <map>

#include "crowd/crowd.h"
#include "model/attach_prop.h"

namespace render {

std::vector<std::vector<std::uint32_t>> impostorPropSets(const crowd::Crowd& crowd) {
    std::vector<std::map<std::uint32_t, std::uint32_t>> carriers(crowd.models().size());
    for (std::uint32_t s = 0; s < crowd.size(); ++s)
        if (crowd.alive(s)) ++carriers[crowd.characters()[s].model][crowd.characters()[s].props];
    std::vector<std::vector<std::uint32_t>> sets(crowd.models().size());
    for (std::size_t m = 0; m < sets.size(); ++m) {
        std::vector<std::pair<std::uint32_t, std::uint32_t>> byShare(carriers[m].begin(), carriers[m].end());
        // Most carriers first; the map's order (smaller mask first) settles ties, as stable_sort keeps it.
        std::stable_sort(byShare.begin(), byShare.end(), [](const auto& a, const auto& b) { return a.second > b.second; });
        for (const auto& [mask, count] : byShare)
            if (sets[m].size() < IMPOSTOR_SETS) sets[m].push_back(mask);
        if (sets[m].empty()) sets[m].push_back(model::propsMostCarry(crowd.model(static_cast<std::uint32_t>(m))));
    }
    return sets;
}

std::uint32_t impostorPropSet(const gpu::ImpostorModel& model, std::uint32_t props) {
    std::uint32_t best = 0, fewest = ~0u;
    for (std::uint32_t s = 0; s < std::min<std::uint32_t>(model.cells.w, IMPOSTOR_SETS); ++s) {
        const auto differing = static_cast<std::uint32_t>(std::popcount(props ^ model.propSets[s]));
        if (differing < fewest) best = s, fewest = differing;
    }
    return best;
}

}  // namespace render
