#include "runtime/rt_main.hpp"

namespace mrd::runtime {

namespace {

ProcessSignals* g_signals = nullptr;

extern "C" void on_stop_signal(int signal) {
  if (g_signals == nullptr) return;
  int none = 0;
  g_signals->stop_signal.compare_exchange_strong(none, signal);
  g_signals->stop.store(true);
}
extern "C" void on_reload_signal(int) {
  if (g_signals != nullptr) g_signals->reload.store(true);
}
extern "C" void on_stats_signal(int) {
  if (g_signals != nullptr) g_signals->print_stats.store(true);
}
extern "C" void on_clear_signal(int) {
  if (g_signals != nullptr) g_signals->clear_latch.store(true);
}

}  // namespace

const char* signal_name(int signal) {
  switch (signal) {
    case SIGTERM: return "SIGTERM";
    case SIGINT: return "SIGINT";
    case SIGHUP: return "SIGHUP";
    default: return "a signal";
  }
}

hal::Timestamp monotonic_now() { return hal::MonotonicClock{}.now(); }

sigset_t install_process_signals(ProcessSignals& signals) {
  static_assert(std::atomic<bool>::is_always_lock_free, "signal handlers set atomic flags");
  static_assert(std::atomic<int>::is_always_lock_free, "signal handlers set atomic flags");
  g_signals = &signals;
  struct sigaction sa{};
  sigemptyset(&sa.sa_mask);
  sa.sa_handler = on_stop_signal;
  sigaction(SIGTERM, &sa, nullptr);
  sigaction(SIGINT, &sa, nullptr);
  sa.sa_handler = on_reload_signal;
  sigaction(SIGHUP, &sa, nullptr);
  sa.sa_handler = on_stats_signal;
  sigaction(SIGUSR1, &sa, nullptr);
  sa.sa_handler = on_clear_signal;
  sigaction(SIGUSR2, &sa, nullptr);
  // A telemetry FIFO (or stdout's pipe) whose reader went away is a write error (EPIPE) the
  // writer counts, not the end of the process.
  sa.sa_handler = SIG_IGN;
  sigaction(SIGPIPE, &sa, nullptr);
  sigset_t mask;
  sigemptyset(&mask);
  for (const int s : {SIGTERM, SIGINT, SIGHUP, SIGUSR1, SIGUSR2}) sigaddset(&mask, s);
  pthread_sigmask(SIG_BLOCK, &mask, nullptr);
  return mask;
}

std::string describe_rt_setup(const RealtimeConfig& config, const RtSetupResult& rt, std::size_t io_threads) {
  std::string text = "real-time: memory ";
  text += rt.memory_locked ? "locked" : "NOT locked";
  text += ", scheduling ";
  text += rt.fifo ? "SCHED_FIFO " + std::to_string(config.priority) : "SCHED_OTHER";
  text += ", cpu ";
  text += rt.pinned ? std::to_string(config.cpu) : "any";
  text += ", bus threads ";
  text += io_threads == 0             ? "none"
          : rt.io_fifo == io_threads ? "SCHED_FIFO " + std::to_string(config.io_priority)
                                     : "SCHED_OTHER";
  text += ", cpu_dma_latency ";
  text += config.cpu_dma_latency < 0 ? "left alone"
          : rt.dma_latency.held()    ? std::to_string(config.cpu_dma_latency) + " us"
                                     : "NOT held";
  return text;
}

}  // namespace mrd::runtime
