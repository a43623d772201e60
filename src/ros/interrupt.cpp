// SIGINT for sim_node (interrupt.h): exit at once while loading, a flag after.
#include "rigid_body_sim/ros/interrupt.h"

#include <unistd.h>

#include <csignal>

namespace rigid_body_sim::node {
namespace {

volatile std::sig_atomic_t g_running = 0;      // the world is loaded
volatile std::sig_atomic_t g_interrupted = 0;  // SIGINT came while running

void onSigint(int) {
  if (g_running == 0) {
    // Only async-signal-safe calls here: write(2) and _exit(2).
    static const char kMessage[] = "sim_node: interrupted while loading the world; exiting\n";
    [[maybe_unused]] const ssize_t n = write(STDERR_FILENO, kMessage, sizeof kMessage - 1);
    _exit(130);  // 128 + SIGINT, as a shell reports it
  }
  g_interrupted = 1;
}

}  // namespace

void installInterruptHandler() {
  struct sigaction action {};
  action.sa_handler = onSigint;
  sigemptyset(&action.sa_mask);
  sigaction(SIGINT, &action, nullptr);
}

void markRunning() { g_running = 1; }

bool interrupted() { return g_interrupted != 0; }

}  // namespace rigid_body_sim::node
