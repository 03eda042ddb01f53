#pragma once
// Setup work (uploads, clears, the impostor bake) that a borrowed device's owner submits: recorded
// later into the host's command buffer instead of a queue submission of the library's own. The
// temporary resources each step needs (staging buffers, bake pipelines) live until the host says
// its submission has finished.
#include <functional>
#include <vector>

#include <vulkan/vulkan.h>

namespace gpu {

class SetupQueue {
public:
    using Record = std::function<void(VkCommandBuffer)>;
    using Release = std::function<void()>;

    SetupQueue() = default;
    ~SetupQueue();
    SetupQueue(const SetupQueue&) = delete;
    SetupQueue& operator=(const SetupQueue&) = delete;

    void add(Record record, Release release);
    // Whether steps wait to be recorded.
    bool pending() const { return !steps_.empty(); }
    // Records every waiting step into `cmd`, then a full memory barrier so that what they wrote is
    // visible to any later command of the queue. Their temporaries wait for releaseRecorded().
    void recordInto(VkCommandBuffer cmd);
    // The host's submission of what recordInto recorded has finished: frees the temporaries.
    void releaseRecorded();

private:
    struct Step {
        Record record;
        Release release;
    };
    std::vector<Step> steps_;
    std::vector<Release> recorded_;
};

// A full memory barrier: every write so far is available and visible to every later command and to
// the host.
void recordFullBarrier(VkCommandBuffer cmd);

}  // namespace gpu
