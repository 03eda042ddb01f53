#include "app/churn_driver.h"

#include <algorithm>
#include <cmath>

namespace app {

double ChurnDriver::update(crowdgpu::Crowd& crowd, double /*time*/) {
    if (living_.empty()) {
        // The crowd's first characters, as a game that made them would hold them.
        for (std::uint32_t s = 0; s < crowd.size(); ++s)
            if (crowd.alive({s, 1u})) {
                living_.push_back(crowd.handle(s));
                looks_.push_back(crowd.character(s));
            }
    }
    const auto count = std::min<std::size_t>(std::lround(share_ * living_.size()), living_.size());
    // Distinct random indices of living_: a partial Fisher-Yates shuffle of its tail.
    picked_.clear();
    leaving_.clear();
    entering_.clear();
    for (std::size_t i = 0; i < count; ++i) {
        const std::size_t last = living_.size() - 1 - i;
        const std::size_t pick = std::uniform_int_distribution<std::size_t>(0, last)(random_);
        std::swap(living_[pick], living_[last]);
        std::swap(looks_[pick], looks_[last]);
        leaving_.push_back(living_[last]);
        crowdgpu::Character entering = looks_[last];
        entering.phase = std::uniform_real_distribution<float>(0.0f, 2.0f)(random_);  // seconds into its clip
        entering_.push_back(entering);
    }
    entered_.resize(entering_.size());
    // The library's part: one batch out, one batch in.
    const double ingest = millisecondsOf([&] {
        crowd.remove(leaving_.data(), leaving_.size());
        crowd.spawn(entering_.data(), entering_.size(), entered_.data());
    });
    const std::size_t first = living_.size() - count;
    for (std::size_t i = 0; i < count; ++i) {
        living_[first + i] = entered_[i];
        looks_[first + i] = entering_[i];
    }
    return ingest;
}

}  // namespace app
