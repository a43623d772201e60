#include "rigid_body_sim/core/parallel.h"

#include <algorithm>
#include <chrono>

#include "rigid_body_sim/core/contact.h"

namespace rigid_body_sim::core {

WorkerPool::WorkerPool(int threads) {
  for (int k = 1; k < threads; ++k) helpers_.emplace_back([this, k] { helper(k); });
}

WorkerPool::~WorkerPool() {
  {
    std::lock_guard<std::mutex> lock(mutex_);
    stop_ = true;
  }
  wake_.notify_all();
  for (std::thread& t : helpers_) t.join();
}

void WorkerPool::run(const std::function<void(int)>& part) {
  {
    std::lock_guard<std::mutex> lock(mutex_);
    job_ = &part;
    pending_.store(static_cast<int>(helpers_.size()), std::memory_order_relaxed);
    generation_.fetch_add(1, std::memory_order_release);
  }
  wake_.notify_all();
  part(0);
  while (pending_.load(std::memory_order_acquire) != 0) {
  }  // the helpers' parts are about as long as ours: spin
}

void WorkerPool::helper(int index) {
  long seen = 0;
  for (;;) {
    // Spin a little (steps come back to back), then sleep until woken.
    const auto spin_until = std::chrono::steady_clock::now() + std::chrono::microseconds(200);
    while (generation_.load(std::memory_order_acquire) == seen && !stop_ &&
           std::chrono::steady_clock::now() < spin_until) {
    }
    const std::function<void(int)>* job;
    {
      std::unique_lock<std::mutex> lock(mutex_);
      wake_.wait(lock, [&] { return stop_ || generation_.load() != seen; });
      if (stop_) return;
      seen = generation_.load();
      job = job_;
    }
    (*job)(index);
    pending_.fetch_sub(1, std::memory_order_acq_rel);
  }
}

/// How many parts to split `work` units into: one unless there is enough
/// work for a second core to pay (and a pool to run it on).
int partsFor(Workspace& ws, std::size_t work) {
  static const int cores = static_cast<int>(std::thread::hardware_concurrency());  // a system call: once
  int threads = ws.threads > 0 ? ws.threads : cores;
  threads = std::max(1, std::min(threads, 8));
  if (threads == 1 || work < ws.min_parallel_work) return 1;  // the hand-over would cost more than it saves
  if (!ws.pool || ws.pool->threads() != threads) ws.pool = std::make_shared<WorkerPool>(threads);
  return threads;
}

}  // namespace rigid_body_sim::core
