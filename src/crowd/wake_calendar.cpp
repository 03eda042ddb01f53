#include "crowd/wake_calendar.h"

#include <algorithm>
#include <cmath>

namespace crowd {

std::int64_t WakeCalendar::bucketOf(double wake) { return static_cast<std::int64_t>(std::floor(wake / kBucketSeconds)); }

void WakeCalendar::file(std::uint32_t character, double wake) {
    if (wake == kNever) return;
    buckets_[bucketOf(wake)].push_back(character);
}

void WakeCalendar::takeDue(double time, const std::function<double(std::uint32_t)>& wakeOf,
                           std::vector<std::uint32_t>& due) {
    due.clear();
    const std::int64_t last = bucketOf(time);
    std::vector<std::uint32_t> later;  // in `last`'s bucket but after `time`: filed again
    while (!buckets_.empty() && buckets_.begin()->first <= last) {
        const auto bucket = buckets_.begin();
        for (const std::uint32_t character : bucket->second) {
            const double wake = wakeOf(character);
            if (wake <= time) due.push_back(character);
            else if (bucketOf(wake) == bucket->first) later.push_back(character);
            // else stale: the character's entry for its current wake is in a later bucket
        }
        buckets_.erase(bucket);
    }
    std::sort(due.begin(), due.end());
    due.erase(std::unique(due.begin(), due.end()), due.end());
    if (!later.empty()) {
        std::sort(later.begin(), later.end());
        later.erase(std::unique(later.begin(), later.end()), later.end());
        buckets_[last] = std::move(later);
    }
}

double WakeCalendar::earliest() const {
    return buckets_.empty() ? kNever : static_cast<double>(buckets_.begin()->first) * kBucketSeconds;
}

}  // namespace crowd
