#include "crowd/worker_pool.h"

#include <algorithm>
#include <memory>

namespace crowd {

WorkerPool::WorkerPool(unsigned threads) {
    for (unsigned i = 1; i < std::max(1u, threads); ++i) threads_.emplace_back([this] { workerLoop(); });
}

WorkerPool::~WorkerPool() {
    {
        std::lock_guard lock(mutex_);
        stopping_ = true;
    }
    wake_.notify_all();
    for (std::thread& t : threads_) t.join();
}

namespace {

std::mutex sharedLock;
std::unique_ptr<WorkerPool> sharedPool;
unsigned sharedCount = 0;  // 0: one per core

unsigned threadsFor(unsigned requested) {
    return requested != 0 ? requested : std::max(1u, std::thread::hardware_concurrency());
}

}  // namespace

WorkerPool& WorkerPool::shared() {
    const std::lock_guard hold(sharedLock);
    if (!sharedPool) sharedPool = std::make_unique<WorkerPool>(threadsFor(sharedCount));
    return *sharedPool;
}

void WorkerPool::setSharedThreads(unsigned threads) {
    const std::lock_guard hold(sharedLock);
    sharedCount = threads;
    sharedPool.reset();  // joins the old workers; the next call makes the new pool
}

unsigned WorkerPool::sharedThreads() {
    const std::lock_guard hold(sharedLock);
    return sharedPool ? static_cast<unsigned>(sharedPool->threads_.size()) + 1u : threadsFor(sharedCount);
}

void WorkerPool::runChunks() {
    for (;;) {
        const std::uint32_t begin = next_.fetch_add(chunk_);
        if (begin >= count_) return;
        (*work_)(begin, std::min(count_, begin + chunk_));
    }
}

void WorkerPool::workerLoop() {
    std::uint64_t seen = 0;
    for (;;) {
        {
            std::unique_lock lock(mutex_);
            wake_.wait(lock, [&] { return stopping_ || generation_ != seen; });
            if (stopping_) return;
            seen = generation_;
            // Woken after its call closed (every chunk taken): nothing to join, and nobody waits for it.
            if (closed_) continue;
            ++active_;
        }
        runChunks();
        {
            std::lock_guard lock(mutex_);
            if (--active_ == 0 && closed_) finished_.notify_one();
        }
    }
}

void WorkerPool::parallelFor(std::uint32_t count, std::uint32_t chunk,
                             const std::function<void(std::uint32_t, std::uint32_t)>& work) {
    if (threads_.empty() || count <= chunk) return work(0, count);
    std::lock_guard caller(callers_);
    {
        std::lock_guard lock(mutex_);
        work_ = &work;
        count_ = count;
        chunk_ = std::max(1u, chunk);
        next_ = 0;
        closed_ = false;
        ++generation_;
    }
    wake_.notify_all();
    runChunks();
    // Every chunk is taken: wait for the workers that joined to finish theirs, not for every worker to
    // wake. A worker the scheduler runs late (a core busy with the driver's threads) used to hold up the
    // whole call, a whole time slice of milliseconds, though the others had done its share: the 10-30 ms
    // planning hitches of a milling crowd on a 16-core host.
    std::unique_lock lock(mutex_);
    closed_ = true;
    finished_.wait(lock, [&] { return active_ == 0; });
}

}  // namespace crowd
