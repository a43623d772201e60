// A tiny fork-join pool: the step splits work over the cores where it pays
// (many awake bodies), in parts whose results do not depend on which thread
// ran them, so runs stay bit-identical with any number of threads.
#pragma once

#include <atomic>
#include <condition_variable>
#include <cstddef>
#include <functional>
#include <mutex>
#include <thread>
#include <vector>

namespace rigid_body_sim::core {

class WorkerPool {
 public:
  /// `threads` in all, the caller's included (helpers = threads − 1).
  explicit WorkerPool(int threads);
  ~WorkerPool();
  WorkerPool(const WorkerPool&) = delete;
  WorkerPool& operator=(const WorkerPool&) = delete;

  int threads() const { return static_cast<int>(helpers_.size()) + 1; }

  /// Calls part(k) for k = 0 … parts − 1 and returns when all are done:
  /// thread t (0 is the caller) runs parts t, t + threads(), …
  void run(int parts, const std::function<void(int)>& part);

 private:
  void helper(int index);

  std::vector<std::thread> helpers_;
  std::mutex mutex_;
  std::condition_variable wake_;
  const std::function<void(int)>* job_ = nullptr;
  int parts_ = 0;
  std::atomic<long> generation_{0};
  std::atomic<int> pending_{0};
  std::atomic<bool> stop_{false};
};

/// The threads a setting asks for: `setting` itself, or every core for 0
/// (std::thread::hardware_concurrency, at least 1).
int threadCount(int setting);

/// Items [begin, end) of part `part` of `parts`: n items in contiguous
/// ranges whose sizes differ by at most one, in order. The core's one split.
struct Range {
  std::size_t begin, end;
};
inline Range partRange(std::size_t n, int part, int parts) {
  return {n * static_cast<std::size_t>(part) / static_cast<std::size_t>(parts),
          n * static_cast<std::size_t>(part + 1) / static_cast<std::size_t>(parts)};
}

/// Runs part(k) for k = 0 … parts − 1: a plain loop on the calling thread
/// without a pool (or for one part: no std::function, no allocation), else
/// on the pool. A part's result must not depend on the thread that runs it.
template <class Part>
void parallelFor(WorkerPool* pool, int parts, Part&& part) {
  if (parts == 1 || pool == nullptr) {
    for (int k = 0; k < parts; ++k) part(k);
  } else {
    pool->run(parts, std::function<void(int)>(std::ref(part)));
  }
}

}  // namespace rigid_body_sim::core
