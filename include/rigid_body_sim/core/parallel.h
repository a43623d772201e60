// A tiny fork-join pool: the step splits work over the cores where it pays
// (many awake bodies), in parts whose results do not depend on which thread
// ran them, so runs stay bit-identical with any number of threads.
#pragma once

#include <atomic>
#include <condition_variable>
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

  /// Calls part(k) for k = 0 … threads() − 1, part 0 on the calling thread,
  /// and returns when all are done.
  void run(const std::function<void(int)>& part);

 private:
  void helper(int index);

  std::vector<std::thread> helpers_;
  std::mutex mutex_;
  std::condition_variable wake_;
  const std::function<void(int)>* job_ = nullptr;
  std::atomic<long> generation_{0};
  std::atomic<int> pending_{0};
  std::atomic<bool> stop_{false};
};

}  // namespace rigid_body_sim::core
