#include "rigid_body_sim/core/step/parallel.h"

#include <algorithm>
#include <chrono>
#include <thread>

namespace rigid_body_sim::core {
namespace {

constexpr int kSpinsBeforeYield = 256;  ///< about a microsecond or two of spinning

}  // namespace

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

void WorkerPool::run(int parts, const std::function<void(int)>& part) {
  {
    std::lock_guard<std::mutex> lock(mutex_);
    job_ = &part;
    parts_ = parts;
    pending_.store(static_cast<int>(helpers_.size()), std::memory_order_relaxed);
    generation_.fetch_add(1, std::memory_order_release);
  }
  wake_.notify_all();
  for (int k = 0; k < parts; k += threads()) part(k);
  // The helpers' parts are about as long as ours: spin, but give the core
  // up now and then. A helper another thread has taken the core from (a
  // ROS node's own threads, on two cores) finishes only once it runs
  // again, and a caller that never yields can hold that core all the while.
  for (int spins = 0; pending_.load(std::memory_order_acquire) != 0; ++spins) {
    if (spins >= kSpinsBeforeYield) std::this_thread::yield();
  }
}

void WorkerPool::helper(int index) {
  long seen = 0;
  for (;;) {
    // Spin a little (steps come back to back), then sleep until woken.
    const auto spin_until = std::chrono::steady_clock::now() + std::chrono::microseconds(200);
    for (int spins = 0;
         generation_.load(std::memory_order_acquire) == seen && !stop_ && std::chrono::steady_clock::now() < spin_until;
         ++spins) {
      if (spins >= kSpinsBeforeYield) std::this_thread::yield();
    }
    const std::function<void(int)>* job;
    int parts;
    {
      std::unique_lock<std::mutex> lock(mutex_);
      wake_.wait(lock, [&] { return stop_ || generation_.load() != seen; });
      if (stop_) return;
      seen = generation_.load();
      job = job_;
      parts = parts_;
    }
    for (int k = index; k < parts; k += threads()) (*job)(k);
    pending_.fetch_sub(1, std::memory_order_acq_rel);
  }
}

int threadCount(int setting) {
  static const int cores = std::max(1, static_cast<int>(std::thread::hardware_concurrency()));  // a system call: once
  return setting > 0 ? setting : cores;
}

}  // namespace rigid_body_sim::core
