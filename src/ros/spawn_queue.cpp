#include "rigid_body_sim/ros/spawn_queue.h"

#include <chrono>
#include <exception>

namespace rigid_body_sim::node {

SpawnBody::Response SpawnQueue::submit(Spawn spawn, const std::function<bool()>& alive) {
  const std::string name = spawn.request.name;
  auto waiting = std::make_shared<Waiting>();
  waiting->spawn = std::move(spawn);
  std::future<SpawnBody::Response> answer = waiting->done.get_future();
  {
    const std::lock_guard<std::mutex> lock(mutex_);
    waiting_.push_back(waiting);
  }
  // The loop adds it at its next tick, paused or not.
  while (answer.wait_for(std::chrono::milliseconds(20)) != std::future_status::ready) {
    if (stopping_ || (alive && !alive())) {
      SpawnBody::Response res;
      res.success = false;
      res.message = "the node is shutting down: body '" + name + "' was not added";
      return res;
    }
  }
  return answer.get();
}

void SpawnQueue::drain(const Insert& insert) {
  std::vector<std::shared_ptr<Waiting>> queued;
  {
    const std::lock_guard<std::mutex> lock(mutex_);
    queued.swap(waiting_);
  }
  for (const auto& w : queued) {
    SpawnBody::Response res;
    try {
      res = insert(w->spawn);
    } catch (const std::exception& e) {
      res.success = false;
      res.message = "body '" + w->spawn.request.name + "' was not added: " + e.what();
    }
    w->done.set_value(res);
  }
}

}  // namespace rigid_body_sim::node
