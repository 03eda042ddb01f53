#pragma once
// Which characters need planning by a given time, found without visiting the others. A milling crowd
// of 1,000,000 replans about 10,000 characters a frame; scanning all of them to find those cost more
// than planning them (16-20 ms a frame on 16 cores, most of it reading every character's agent).
// Each character is filed under the time its plan next runs out, in buckets of kBucketSeconds; a
// frame takes the buckets up to its time. A character whose wake time changes is filed again; its old
// entry goes stale and is dropped when its bucket comes up.
#include <cstdint>
#include <functional>
#include <limits>
#include <map>
#include <vector>

namespace crowd {

class WakeCalendar {
public:
    static constexpr double kBucketSeconds = 1.0 / 32.0;
    static constexpr double kNever = std::numeric_limits<double>::infinity();

    void clear() { buckets_.clear(); }
    // Files `character` to wake at `wake` seconds (kNever: never; not filed).
    void file(std::uint32_t character, double wake);
    // Every character whose current wake time (`wakeOf`) is at or before `time`, ascending and each
    // once, taken out of the calendar; the caller files them again once planned. Entries that went
    // stale (their character's wake moved to another bucket) are dropped. `wakeOf` is called on the
    // shared worker pool's threads.
    void takeDue(double time, const std::function<double(std::uint32_t)>& wakeOf, std::vector<std::uint32_t>& due);
    // No character wakes before this time (a lower bound; kNever when nobody is filed).
    double earliest() const;

private:
    static std::int64_t bucketOf(double wake);
    std::map<std::int64_t, std::vector<std::uint32_t>> buckets_;
    // takeDue's scratch, kept to spare a frame its allocations: the entries taken, their buckets, kinds.
    std::vector<std::uint32_t> taken_;
    std::vector<std::int64_t> takenBuckets_;
    std::vector<std::uint8_t> kinds_;
};

}  // namespace crowd
