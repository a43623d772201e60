// What a caller passes to step() besides the model and the state: the knobs
// of how the step runs (threads, fixed points) and what it reports (the
// contacts, the deepest penetration). The stages' scratch memory lives here
// too, behind a pointer to a type private to the core (src/core/scratch.h),
// as MuJoCo keeps its arena in mjData: results never depend on it, so a
// fresh workspace or a reused one, one thread or two, give bit-identical steps.
#pragma once

#include <cstddef>
#include <memory>
#include <string>
#include <vector>

#include "rigid_body_sim/core/contacts/contact.h"

namespace rigid_body_sim::core {

namespace detail {
struct StepScratch;
}

/// A body the step's guard put back (docs/physics.md §5.9).
struct Divergence {
  int body = 0;      ///< index in the model
  std::string what;  ///< what was not finite: "position, velocity", ...
};

struct Workspace {
  Workspace();
  ~Workspace();
  Workspace(Workspace&&) noexcept;
  Workspace& operator=(Workspace&&) noexcept;

  // ---- knobs (none changes a result)
  /// Threads the step may use, the caller's included: 0 = every core
  /// (std::thread::hardware_concurrency). The step only splits work when
  /// enough is awake for it to pay.
  int threads = 0;
  /// Awake bodies (or contacts) below which a stage runs on one thread: a
  /// hand-over to the other core costs about 1–1.5 µs, and an awake body's
  /// step 0.5–1.5 µs (bench/HISTORY.md).
  std::size_t min_parallel_work = 32;
  /// Take a step that would return its input unchanged as such (fixed_point.h);
  /// false computes every step (the tests compare the two, state for state).
  bool skip_fixed_points = true;

  // ---- outputs of the last step
  std::vector<Contact> contacts;     ///< sorted by key (body, other, item, point)
  double deepest_penetration = 0.0;  ///< m, ≥ 0, seen in this step's detection
  std::size_t skipped_steps = 0;     ///< steps found to be a fixed point and not computed again (a count)
  /// Bodies whose velocity the speed limits (SpeedLimits) scaled back in
  /// this step, ascending: the caller says so, once per body.
  std::vector<int> speed_limited;
  /// Bodies whose state stopped being finite in this step, put back to
  /// their pose before it, at rest: the caller clears their loads and says so.
  std::vector<Divergence> diverged;

  /// A workspace for a model edited since this one stepped it (a body added
  /// or removed): the same knobs and worker threads, none of the caches,
  /// which assumed the old model; this one is left empty.
  Workspace forEditedModel();

  /// The stages' scratch memory; not for callers.
  std::unique_ptr<detail::StepScratch> scratch;
};

}  // namespace rigid_body_sim::core
