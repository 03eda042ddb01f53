#pragma once
// --churn PERCENT: a live population for benchmarks. Every frame that share of the crowd's living
// characters leaves, chosen at random, and as many enter in the slots they left, each where the one
// before stood but at another phase: the crowd keeps its size and its look while the renderer uploads
// only the slots that changed. It holds its characters' handles, as a game does, and hands the library
// one batch of removals and one of spawns a frame.
#include <cstdint>
#include <random>
#include <vector>

#include "app/crowd_driver.h"

namespace app {

class ChurnDriver : public CrowdDriver {
public:
    // `share`: of the living characters, a frame (0.01: 1 %).
    ChurnDriver(double share, std::uint32_t seed) : share_(share), random_(seed) {}
    double update(crowdgpu::Crowd& crowd, double time) override;

private:
    double share_;
    std::mt19937 random_;
    std::vector<crowdgpu::CharacterHandle> living_;     // the game's own list of its characters
    std::vector<crowdgpu::Character> looks_;            // and what each looks like, by the same index
    std::vector<std::uint32_t> picked_;                 // indices into living_ leaving this frame
    std::vector<crowdgpu::CharacterHandle> leaving_;
    std::vector<crowdgpu::Character> entering_;
    std::vector<crowdgpu::CharacterHandle> entered_;
};

}  // namespace app
