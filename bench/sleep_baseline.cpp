// The floor for the node's step-period jitter on this machine: a loop that
// does nothing but sleep until the next millisecond (with the same 1 us timer
// slack the node asks for). Prints |period − 1 ms| p50/p99/max over N ticks.
#include <sys/prctl.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <thread>
#include <vector>

int main(int argc, char** argv) {
  const int ticks = argc > 1 ? std::atoi(argv[1]) : 10000;
  prctl(PR_SET_TIMERSLACK, 1000UL, 0UL, 0UL, 0UL);
  using Clock = std::chrono::steady_clock;
  auto next = Clock::now();
  auto last = next;
  std::vector<double> dev;
  for (int i = 0; i < ticks; ++i) {
    next += std::chrono::microseconds(1000);
    std::this_thread::sleep_until(next);
    const auto now = Clock::now();
    dev.push_back(std::abs(std::chrono::duration<double>(now - last).count() - 1e-3));
    last = now;
  }
  std::sort(dev.begin(), dev.end());
  std::printf("%zu ticks, |period - 0.001 s| p50 %.1f us, p99 %.1f us, max %.1f us\n", dev.size(),
              1e6 * dev[dev.size() / 2], 1e6 * dev[dev.size() * 99 / 100], 1e6 * dev.back());
}
