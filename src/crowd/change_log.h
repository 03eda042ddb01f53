#pragma once
// Which slots changed since a reader last looked: what a renderer uploads instead of the whole crowd.
// Changes (a replan, a spawn, a removal, a driven character's new keys) are marked in the open
// generation; a reader seals it when it takes the changes for a frame, and next time asks for those
// after the generation it sealed. A reader that fell too far behind (or a frame it recorded that never
// ran, render/frame_ledger.h) asks from further back: the log keeps the last kKeptGenerations sealed
// generations, and beyond them the reader takes every slot.
//
// The same slot may change many times between two looks: each generation lists it once, and a reader
// visits it once, for its latest change (what it uploads is the slot's state now, never a difference,
// so sending a slot again is harmless).
#include <cstdint>
#include <deque>
#include <vector>

namespace crowd {

class ChangeLog {
public:
    static constexpr std::uint64_t kEverything = ~0ull;  // a reader that has seen nothing yet
    static constexpr std::size_t kKeptGenerations = 16;

    explicit ChangeLog(std::uint32_t slots = 0) : changedAt_(slots, 0u) {}

    // `slot` changed (in the open generation).
    void mark(std::uint32_t slot);
    // mark in two steps, for a batch of distinct slots marked on several threads: claim(slot) touches
    // the slot alone and says whether it is new to the open generation; list(slot) then lists each such
    // slot, on one thread.
    bool claim(std::uint32_t slot) {
        const std::uint64_t open = openGeneration();
        if (changedAt_[slot] == open) return false;
        changedAt_[slot] = open;
        return true;
    }
    void list(std::uint32_t slot) { open_.push_back(slot); }
    // Every slot changed (a new epoch restates every record): readers from before it take every slot.
    void markAll() { everythingAt_ = openGeneration(); }

    // Closes the open generation and returns it: a reader then has every change up to it.
    std::uint64_t seal();
    std::uint64_t openGeneration() const { return first_ + generations_.size() + 1; }

    // Calls f(slot) once for each slot changed after generation `since` (everything when `since` is
    // kEverything), changes of the open generation included. Returns false, calling nothing, when
    // the reader must take every slot instead (it saw nothing yet, every slot changed since, or the log
    // no longer reaches back to `since`).
    template <class F>
    bool forEachSince(std::uint64_t since, F&& f) const {
        if (since == kEverything || since < first_ || (everythingAt_ != kNone && everythingAt_ > since)) return false;
        for (std::uint64_t g = since + 1; g <= openGeneration(); ++g)
            for (const std::uint32_t slot : slotsOf(g))
                if (changedAt_[slot] == g) f(slot);  // its latest change: a later generation lists it again
        return true;
    }
    // How many slot changes forEachSince(since) would visit at most (its lists' lengths).
    std::size_t pendingSince(std::uint64_t since) const;

private:
    static constexpr std::uint64_t kNone = ~0ull;
    const std::vector<std::uint32_t>& slotsOf(std::uint64_t generation) const {
        return generation == openGeneration() ? open_ : generations_[generation - first_ - 1];
    }

    std::vector<std::uint64_t> changedAt_;  // per slot: the generation of its latest change (0: none)
    std::deque<std::vector<std::uint32_t>> generations_;  // the sealed ones kept: first_ + 1 onwards
    std::vector<std::uint32_t> open_;                     // the open generation's
    std::uint64_t first_ = 0;  // generations up to this one are forgotten
    std::uint64_t everythingAt_ = kNone;
};

}  // namespace crowd
