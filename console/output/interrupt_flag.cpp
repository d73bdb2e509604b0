#include "console/output/interrupt_flag.hpp"

#include <csignal>

namespace stride::console {
namespace {

// A signal handler can reach only process-wide state; one flag serves the one live InterruptFlag.
volatile std::sig_atomic_t g_signal = 0;
struct sigaction g_previous_int {
}, g_previous_term{};

void on_signal(int sig) {
  if (g_signal != 0) {  // asked twice: stop now
    std::signal(sig, SIG_DFL);
    std::raise(sig);
    return;
  }
  g_signal = sig;
}

}  // namespace

InterruptFlag::InterruptFlag() {
  g_signal = 0;
  struct sigaction action {};
  action.sa_handler = on_signal;
  sigemptyset(&action.sa_mask);
  sigaction(SIGINT, &action, &g_previous_int);
  sigaction(SIGTERM, &action, &g_previous_term);
}

InterruptFlag::~InterruptFlag() {
  sigaction(SIGINT, &g_previous_int, nullptr);
  sigaction(SIGTERM, &g_previous_term, nullptr);
  g_signal = 0;
}

bool InterruptFlag::raised() const {
  return g_signal != 0;
}

int InterruptFlag::signal() const {
  return g_signal;
}

}  // namespace stride::console
