#include "crowd/population.h"

namespace crowd {

Population::Population(std::vector<std::uint32_t> slotModels, std::uint32_t initial, std::uint32_t modelCount)
    : slots_(slotModels.size()), capacity_(modelCount, 0u), free_(modelCount) {
    for (std::uint32_t s = 0; s < slots(); ++s) {
        slots_[s].model = static_cast<std::uint16_t>(slotModels[s]);
        ++capacity_[slotModels[s]];
        if (s < initial) {
            slots_[s].alive = 1u;
            slots_[s].generation = 1u;
            ++live_;
        }
    }
    for (std::uint32_t s = slots(); s-- > initial;) free_[slotModels[s]].push_back(s);
}

std::optional<Handle> Population::take(std::uint32_t model) {
    if (model >= free_.size() || free_[model].empty()) return std::nullopt;
    const std::uint32_t slot = popFree(model);
    const std::uint32_t generation = admit(slot);
    admitted(1);
    return Handle{slot, generation};
}

std::uint32_t Population::popFree(std::uint32_t model) {
    const std::uint32_t slot = free_[model].back();
    free_[model].pop_back();
    return slot;
}

std::uint32_t Population::admit(std::uint32_t slot) {
    slots_[slot].alive = 1u;
    return ++slots_[slot].generation;
}

void Population::admitted(std::uint32_t count) {
    live_ += count;
    ++version_;
}

void Population::release(std::uint32_t slot) {
    if (!alive(slot)) return;
    slots_[slot].alive = 0u;
    --live_;
    ++version_;
    free_[slots_[slot].model].push_back(slot);  // the next character of the model takes it first
}

void Population::restore(Handle handle) {
    free_[slots_[handle.slot].model].pop_back();
    slots_[handle.slot].alive = 1u;
    ++live_;
    ++version_;
}

std::string Population::name(Handle handle) {
    return "character (slot " + std::to_string(handle.slot) + ", generation " + std::to_string(handle.generation) + ")";
}

std::string Population::whyInvalid(Handle handle) const {
    const std::string name = Population::name(handle);
    if (handle.slot >= slots())
        return name + ": no such slot (the crowd has " + std::to_string(slots()) + ")";
    if (handle.generation == 0 || handle.generation > slots_[handle.slot].generation)
        return name + ": never made (the slot's latest is generation " + std::to_string(slots_[handle.slot].generation) + ")";
    if (handle.generation < slots_[handle.slot].generation)
        return name + ": removed (the slot holds generation " + std::to_string(slots_[handle.slot].generation) + " now)";
    return slots_[handle.slot].alive ? std::string() : name + ": removed";
}

}  // namespace crowd
