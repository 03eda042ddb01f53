#include "crowd/change_log.h"

namespace crowd {

void ChangeLog::mark(std::uint32_t slot) {
    if (claim(slot)) list(slot);
}

std::uint64_t ChangeLog::seal() {
    const std::uint64_t sealed = openGeneration();
    generations_.push_back(std::move(open_));
    open_.clear();
    // A list kept is a list a late reader may still visit; older readers take every slot. The oldest
    // list's memory becomes the open one's (a frame of 20,000 changes allocates nothing).
    while (generations_.size() > kKeptGenerations) {
        open_ = std::move(generations_.front());
        open_.clear();
        generations_.pop_front();
        ++first_;
    }
    return sealed;
}

std::size_t ChangeLog::pendingSince(std::uint64_t since) const {
    if (since == kEverything || since < first_) return changedAt_.size();
    std::size_t total = 0;
    for (std::uint64_t g = since + 1; g <= openGeneration(); ++g) total += slotsOf(g).size();
    return total;
}

}  // namespace crowd
