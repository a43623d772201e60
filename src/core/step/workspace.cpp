#include "rigid_body_sim/core/step/workspace.h"

#include "scratch.h"

namespace rigid_body_sim::core {

Workspace::Workspace() : scratch(std::make_unique<detail::StepScratch>()) {}
Workspace::~Workspace() = default;
Workspace::Workspace(Workspace&&) noexcept = default;
Workspace& Workspace::operator=(Workspace&&) noexcept = default;

Workspace Workspace::forEditedModel() {
  Workspace fresh;
  fresh.threads = threads;
  fresh.min_parallel_work = min_parallel_work;
  fresh.skip_fixed_points = skip_fixed_points;
  if (scratch) fresh.scratch->pool = std::move(scratch->pool);  // threads are not a cache
  *this = Workspace();
  return fresh;
}

namespace detail {

int partsFor(Workspace& ws, std::size_t work) {
  StepScratch& sc = *ws.scratch;
  const int threads = threadCount(ws.threads);
  const int parts = threads == 1 || work < ws.min_parallel_work ? 1 : threads;  // a hand-over costs more than it saves
  if (parts > 1 && (!sc.pool || sc.pool->threads() != threads)) sc.pool = std::make_shared<WorkerPool>(threads);
  if (sc.parts.size() < static_cast<std::size_t>(parts)) sc.parts.resize(parts);
  return parts;
}

}  // namespace detail
}  // namespace rigid_body_sim::core
