#pragma once
// The device memory a renderer will allocate for a crowd, item by item, computed before any
// allocation from the sizes the constructors use (the same bucket, bone, impostor and method
// planners): what a host checks against its heap, and what the programs refuse a crowd by.
#include <cstdint>
#include <vector>

#include "frame/crowd_recorder.h"

namespace frame {

struct MemoryPlan {
    std::vector<skin::MemoryItem> items;
    std::uint64_t total() const;
};

MemoryPlan planMemory(const gpu::VulkanContext& context, const crowd::Crowd& crowd, const RecorderOptions& options);

}  // namespace frame
