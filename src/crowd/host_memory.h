#pragma once
// Host memory a crowd takes before it is built, and what the machine has free, so that a program can
// refuse a crowd too large for the host in one line instead of allocating until it is killed.
#include <cstdint>
#include <span>

#include "model/skinned_model.h"

namespace crowd {

// Bytes a crowd of `characters` of these models takes on the host, counting each character at the
// largest model's joints (errs high): its Crowd state (character, agent, motion segment, key cursors,
// bookkeeping; twice, as the vectors grow by doubling), the renderer's record and bone offset, and,
// with `cpuPalettes`, one bone matrix per joint (the CPU animation jobs' output).
std::uint64_t estimateHostBytes(std::span<const model::SkinnedModel* const> models, std::uint64_t characters,
                                bool cpuPalettes);

}  // namespace crowd
