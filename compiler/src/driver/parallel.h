// ParallelFor: runs fn(i) for i in [0, n) on up to `jobs` threads. Results must be written by
// index, so output order never depends on scheduling.
#ifndef KILN_DRIVER_PARALLEL_H_
#define KILN_DRIVER_PARALLEL_H_

#include <algorithm>
#include <atomic>
#include <chrono>
#include <condition_variable>
#include <cstddef>
#include <functional>
#include <mutex>
#include <thread>
#include <vector>

namespace kiln::driver {

inline unsigned ResolveJobs(unsigned jobs) {
    if (jobs > 0)
        return jobs;
    return std::max(1u, std::thread::hardware_concurrency());
}

// `done` is called on the calling thread roughly as items finish (for progress lines).
inline void ParallelFor(size_t n,
                        unsigned jobs,
                        const std::function<void(size_t)>& fn,
                        const std::function<void(size_t)>& done = {}) {
    std::atomic<size_t> next{0}, finished{0};
    std::mutex mu;
    std::condition_variable all_done;
    auto worker = [&] {
        for (size_t i = next++; i < n; i = next++) {
            fn(i);
            if (++finished == n) {
                std::lock_guard<std::mutex> lock(mu);
                all_done.notify_all();
            }
        }
    };
    const unsigned threads = static_cast<unsigned>(std::min<size_t>(ResolveJobs(jobs), n));
    std::vector<std::thread> pool;
    for (unsigned t = 1; t < threads; ++t)
        pool.emplace_back(worker);
    if (!done) {
        worker();
    } else {
        std::thread last(worker);
        // Progress every 50 ms, and no wait past the last item.
        std::unique_lock<std::mutex> lock(mu);
        while (finished.load() < n) {
            lock.unlock();
            done(finished.load());
            lock.lock();
            all_done.wait_for(lock, std::chrono::milliseconds(50),
                              [&] { return finished.load() >= n; });
        }
        lock.unlock();
        last.join();
        done(n);
    }
    for (std::thread& t : pool)
        t.join();
}

}  // namespace kiln::driver

#endif  // KILN_DRIVER_PARALLEL_H_
