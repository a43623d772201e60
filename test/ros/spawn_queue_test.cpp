// The spawn hand-over (no master): a spawn queued on one thread is added by
// the loop's next drain and answered; what the insert throws is the answer;
// once the loop has ended, a waiting spawn is refused, never left hanging.
#include "rigid_body_sim/ros/spawn_queue.h"

#include <gtest/gtest.h>

#include <chrono>
#include <stdexcept>
#include <thread>

namespace rigid_body_sim::node {
namespace {

SpawnQueue::Spawn named(const std::string& name) {
  SpawnQueue::Spawn s;
  s.request.name = name;
  return s;
}

/// Drains `queue` until `answered`, as the loop's ticks do.
void drainUntil(SpawnQueue& queue, const std::atomic<bool>& answered, const SpawnQueue::Insert& insert) {
  while (!answered) {
    queue.drain(insert);
    std::this_thread::sleep_for(std::chrono::milliseconds(1));
  }
}

TEST(SpawnQueue, TheLoopAddsAQueuedSpawnAndAnswersIt) {
  SpawnQueue queue;
  std::atomic<bool> answered{false};
  SpawnBody::Response res;
  std::thread spawner([&] {
    res = queue.submit(named("ball"));
    answered = true;
  });
  std::vector<std::string> inserted;
  drainUntil(queue, answered, [&](SpawnQueue::Spawn& s) {
    inserted.push_back(s.request.name);
    SpawnBody::Response r;
    r.success = true;
    r.message = "added " + s.request.name;
    return r;
  });
  spawner.join();
  EXPECT_TRUE(res.success);
  EXPECT_EQ(res.message, "added ball");
  EXPECT_EQ(inserted, std::vector<std::string>{"ball"});  // once
}

TEST(SpawnQueue, WhatTheInsertThrowsIsTheAnswer) {
  SpawnQueue queue;
  std::atomic<bool> answered{false};
  SpawnBody::Response res;
  std::thread spawner([&] {
    res = queue.submit(named("box"));
    answered = true;
  });
  drainUntil(queue, answered, [](SpawnQueue::Spawn&) -> SpawnBody::Response { throw std::runtime_error("no room"); });
  spawner.join();
  EXPECT_FALSE(res.success);
  EXPECT_EQ(res.message, "body 'box' was not added: no room");
}

TEST(SpawnQueue, AWaitingSpawnIsRefusedOnceTheLoopHasEnded) {
  SpawnQueue queue;
  SpawnBody::Response res;
  std::thread spawner([&] { res = queue.submit(named("late")); });
  std::this_thread::sleep_for(std::chrono::milliseconds(30));
  queue.stop();  // no drain ever comes
  spawner.join();
  EXPECT_FALSE(res.success);
  EXPECT_EQ(res.message, "the node is shutting down: body 'late' was not added");
  // And one that comes later, or while ROS shuts down, as well.
  EXPECT_FALSE(queue.submit(named("later")).success);
  SpawnQueue other;
  EXPECT_FALSE(other.submit(named("x"), [] { return false; }).success);
}

}  // namespace
}  // namespace rigid_body_sim::node
