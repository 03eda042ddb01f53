#include "crowd/wake_calendar.h"

#include <algorithm>
#include <cmath>

#include "crowd/worker_pool.h"

namespace crowd {

std::int64_t WakeCalendar::bucketOf(double wake) {
    // Clamped before the conversion, which is undefined past int64 (a wake of 1e300 s) or for NaN.
    constexpr double kFarthest = 4.0e18;
    const double bucket = std::floor(wake / kBucketSeconds);
    return static_cast<std::int64_t>(bucket > -kFarthest ? std::min(bucket, kFarthest) : -kFarthest);
}

void WakeCalendar::file(std::uint32_t character, double wake) {
    if (wake == kNever) return;
    buckets_[bucketOf(wake)].push_back(character);
}

void WakeCalendar::takeDue(double time, const std::function<double(std::uint32_t)>& wakeOf,
                           std::vector<std::uint32_t>& due) {
    // The entries of every bucket up to `time`'s, with their bucket.
    const std::int64_t last = bucketOf(time);
    taken_.clear();
    takenBuckets_.clear();
    while (!buckets_.empty() && buckets_.begin()->first <= last) {
        const auto bucket = buckets_.begin();
        taken_.insert(taken_.end(), bucket->second.begin(), bucket->second.end());
        takenBuckets_.resize(taken_.size(), bucket->first);
        buckets_.erase(bucket);
    }
    // Each entry's wake, read on every core: a frame takes thousands of entries, and each read is a
    // character's agent somewhere in a crowd of millions (one core took 0.45 ms a frame at 1,000,000).
    kinds_.resize(taken_.size());
    enum : std::uint8_t { kDue, kLater, kStale };
    WorkerPool::shared().parallelFor(static_cast<std::uint32_t>(taken_.size()), 512,
                                     [&](std::uint32_t begin, std::uint32_t end) {
                                         for (std::uint32_t i = begin; i < end; ++i) {
                                             const double wake = wakeOf(taken_[i]);
                                             kinds_[i] = wake <= time                              ? kDue
                                                         : bucketOf(wake) == takenBuckets_[i] ? kLater
                                                                                               : kStale;
                                         }
                                     });
    due.clear();
    std::vector<std::uint32_t> later;  // in `last`'s bucket but after `time`: filed again
    for (std::size_t i = 0; i < taken_.size(); ++i) {
        if (kinds_[i] == kDue) due.push_back(taken_[i]);
        else if (kinds_[i] == kLater) later.push_back(taken_[i]);
        // else stale: the character's entry for its current wake is in a later bucket
    }
    std::sort(due.begin(), due.end());
    due.erase(std::unique(due.begin(), due.end()), due.end());
    // In any order and not made unique: a character filed twice comes up twice, and `due` is.
    if (!later.empty()) buckets_[last] = std::move(later);
}

double WakeCalendar::earliest() const {
    return buckets_.empty() ? kNever : static_cast<double>(buckets_.begin()->first) * kBucketSeconds;
}

}  // namespace crowd
