// rbsim's loop, for a world and a robot alike: the steps run in blocks
// between the CSV's rows and the progress bar's updates, and only the
// blocks are timed, so ns_per_step excludes writing.
#pragma once

#include <algorithm>
#include <chrono>

#include "rbsim_output.h"

namespace rigid_body_sim::tools {

struct LoopTimes {
  double wall_s = 0.0;       ///< the whole loop, writing included
  double ns_per_step = 0.0;  ///< stepping only
};

/// Calls step(n) for n = 1 … steps. With `rows`, write(n) writes the CSV's
/// row after step n: at n = 0, every `every` steps and after the last.
/// `progress` (stderr a terminal, a long run) shows a bar.
template <class Step, class Write>
LoopTimes runLoop(long long steps, bool rows, long long every, bool progress, Step&& step, Write&& write) {
  ProgressBar bar(steps, progress);
  const long long progress_every = std::max(1LL, steps / 100);
  using Clock = std::chrono::steady_clock;
  const auto wall_start = Clock::now();
  Clock::duration stepping{0};
  if (rows) write(0LL);
  long long done = 0;
  while (done < steps) {
    long long block = steps - done;
    if (rows) block = std::min(block, every - done % every);
    block = std::min(block, progress_every - done % progress_every);
    const auto t0 = Clock::now();
    for (long long k = 1; k <= block; ++k) step(done + k);
    stepping += Clock::now() - t0;
    done += block;
    if (rows && (done % every == 0 || done == steps)) write(done);
    if (done % progress_every == 0 || done == steps) bar.show(done);
  }
  return {std::chrono::duration<double>(Clock::now() - wall_start).count(),
          std::chrono::duration<double, std::nano>(stepping).count() / static_cast<double>(steps)};
}

}  // namespace rigid_body_sim::tools
