#include "impact3d/solve/sense_switches.h"

namespace impact3d {

namespace {

volatile std::sig_atomic_t g_stop = 0;        // SIGINT, SIGTERM (sw1)
volatile std::sig_atomic_t g_status = 0;      // SIGUSR1 (sw2)
volatile std::sig_atomic_t g_plot_now = 0;    // SIGUSR2 (sw4)
extern "C" void on_stop_signal(int) { g_stop = 1; }
extern "C" void on_status_signal(int) { g_status = 1; }
extern "C" void on_plot_signal(int) { g_plot_now = 1; }

bool take(volatile std::sig_atomic_t& flag) {
  if (!flag) return false;
  flag = 0;
  return true;
}

}  // namespace

SenseSwitches::SenseSwitches() {
  g_stop = 0;
  g_status = 0;
  g_plot_now = 0;
  struct sigaction sa {};
  sigemptyset(&sa.sa_mask);
  sa.sa_handler = on_stop_signal;
  sigaction(SIGINT, &sa, &old_int_);
  sigaction(SIGTERM, &sa, &old_term_);
  sa.sa_handler = on_status_signal;
  sigaction(SIGUSR1, &sa, &old_usr1_);
  sa.sa_handler = on_plot_signal;
  sigaction(SIGUSR2, &sa, &old_usr2_);
}

SenseSwitches::~SenseSwitches() {
  sigaction(SIGINT, &old_int_, nullptr);
  sigaction(SIGTERM, &old_term_, nullptr);
  sigaction(SIGUSR1, &old_usr1_, nullptr);
  sigaction(SIGUSR2, &old_usr2_, nullptr);
}

bool SenseSwitches::take_stop() { return take(g_stop); }
bool SenseSwitches::take_status() { return take(g_status); }
bool SenseSwitches::take_plot_request(bool state_at_this_time) {
  return !state_at_this_time && take(g_plot_now);
}

}  // namespace impact3d
