#pragma once
// Who is in the crowd: a fixed set of slots, each for one model, declared when the crowd is made (its
// capacity), of which some hold a living character. A host adds characters into free slots of their
// model and removes them; a slot is reused by the next character of the same model. Every slot's model
// is fixed for the crowd's life, so whatever the renderer lays out per slot (bone blocks, per-model
// lists, skinned vertices of the fixed layout) stays valid however the population changes.
//
// A character is named by a handle: its slot and the slot's generation, which counts the characters the
// slot has held. A handle whose character was removed (or whose slot holds a newer one) is stale.
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

namespace crowd {

struct Handle {
    std::uint32_t slot = 0;
    std::uint32_t generation = 0;  // 0: no character ever (a handle that is never valid)
};

class Population {
public:
    // Slot s holds model slotModels[s]; the first `initial` slots hold living characters (generation 1),
    // the others are free.
    Population(std::vector<std::uint32_t> slotModels, std::uint32_t initial, std::uint32_t modelCount);

    std::uint32_t slots() const { return static_cast<std::uint32_t>(slots_.size()); }
    std::uint32_t live() const { return live_; }
    std::uint32_t modelOf(std::uint32_t slot) const { return slots_[slot].model; }
    bool alive(std::uint32_t slot) const { return slot < slots() && slots_[slot].alive != 0; }
    std::uint32_t generation(std::uint32_t slot) const { return slots_[slot].generation; }
    Handle handle(std::uint32_t slot) const { return {slot, slots_[slot].generation}; }
    // The handle names the character its slot holds now.
    bool valid(Handle handle) const {
        return alive(handle.slot) && handle.generation != 0 && slots_[handle.slot].generation == handle.generation;
    }
    // Slots of `model` in all, and free now.
    std::uint32_t capacityOf(std::uint32_t model) const { return capacity_[model]; }
    std::uint32_t freeOf(std::uint32_t model) const { return static_cast<std::uint32_t>(free_[model].size()); }

    // A free slot of `model`, now living under a new generation; none when every slot of the model is taken.
    std::optional<Handle> take(std::uint32_t model);
    // take in three steps, for a batch whose slots are admitted on several threads: popFree takes a free
    // slot of `model` off its list (there must be one), admit(slot) makes it living under a new
    // generation and returns that (touching the slot alone: threads may admit different slots at once),
    // and admitted(count) counts them in once all are.
    std::uint32_t popFree(std::uint32_t model);
    std::uint32_t admit(std::uint32_t slot);
    void admitted(std::uint32_t count);
    // The slot's character leaves; the slot is free for the next character of its model.
    void release(std::uint32_t slot);
    // Undoes the latest release, of `handle`'s slot (a batch refused half way through: releases are
    // restored newest first, so each slot is on top of its model's free list).
    void restore(Handle handle);

    // Counts the spawns and removals so far: two reads that differ saw the population change between.
    std::uint64_t version() const { return version_; }

    // "character 12 (slot 12, generation 3) was removed" and the like: why `handle` is not valid.
    std::string whyInvalid(Handle handle) const;
    // "character (slot 12, generation 3)".
    static std::string name(Handle handle);

private:
    // A slot's state in 8 bytes: checking a handle and releasing its slot is one cache miss.
    struct Slot {
        std::uint32_t generation = 0;
        std::uint16_t model = 0;  // below kMaxCrowdModels
        std::uint8_t alive = 0;
    };
    std::vector<Slot> slots_;
    std::vector<std::uint32_t> capacity_;
    // Per model: its free slots, a stack: the slot freed last is taken first (at the start, the lowest).
    std::vector<std::vector<std::uint32_t>> free_;
    std::uint32_t live_ = 0;
    std::uint64_t version_ = 0;
};

}  // namespace crowd
