#pragma once
// A fixed set of worker threads that split a loop over characters: started once, so a frame pays
// no thread creation, and a small crowd can still use every core.
#include <atomic>
#include <condition_variable>
#include <cstdint>
#include <functional>
#include <mutex>
#include <thread>
#include <vector>

namespace crowd {

class WorkerPool {
public:
    explicit WorkerPool(unsigned threads = std::thread::hardware_concurrency());
    ~WorkerPool();
    WorkerPool(const WorkerPool&) = delete;
    WorkerPool& operator=(const WorkerPool&) = delete;

    // Calls work(begin, end) over [0, count) in chunks of `chunk`, on the workers and the calling
    // thread, and returns once every chunk is done. Callers on several threads take turns (the shared
    // pool serves every crowd a host may advance on its own thread); not reentrant from inside `work`.
    void parallelFor(std::uint32_t count, std::uint32_t chunk,
                     const std::function<void(std::uint32_t, std::uint32_t)>& work);

    // The pool shared by the process: setSharedThreads's count, else one thread per core (the caller's
    // included, so one worker fewer).
    static WorkerPool& shared();
    // Makes the shared pool again with `threads` threads, the caller's included (0: one per core; 1: no
    // workers, every call on the caller's thread). Not while any thread is inside one of its calls.
    static void setSharedThreads(unsigned threads);
    // The shared pool's threads, the caller's included.
    static unsigned sharedThreads();

private:
    void workerLoop();
    void runChunks();

    std::mutex callers_;  // held for a whole parallelFor: one caller's work at a time
    std::mutex mutex_;
    std::condition_variable wake_;
    std::condition_variable finished_;
    const std::function<void(std::uint32_t, std::uint32_t)>* work_ = nullptr;
    std::uint32_t count_ = 0;
    std::uint32_t chunk_ = 1;
    std::atomic<std::uint32_t> next_{0};
    std::uint64_t generation_ = 0;
    unsigned active_ = 0;  // workers that joined the current call and have not finished
    bool closed_ = true;   // every chunk of the current call is taken: late wakers do not join
    bool stopping_ = false;
    std::vector<std::thread> threads_;
};

}  // namespace crowd
