#pragma once

#include <time.h>

#include <atomic>
#include <chrono>
#include <cstdint>

#include "runtime/loop_statistics.hpp"
#include "hal/clock.hpp"

namespace mrd::runtime {

// Keeps a fixed period with clock_nanosleep(CLOCK_MONOTONIC, TIMER_ABSTIME) on absolute
// release times, so the period does not drift with the cycle's own duration. A cycle that runs
// past its period skips the missed releases (no catch-up burst); they are counted as overruns,
// ceil(elapsed / period) - 1 for that cycle, and the next release stays on the original grid.
class RealTimeRunner {
 public:
  explicit RealTimeRunner(std::chrono::nanoseconds period) : period_(period) {}

  // Calls cycle(release) once per period until `stop` is set or `max_cycles` have run
  // (0: no limit). Returns the release time the next cycle would have had.
  template <typename Cycle>
  hal::Timestamp run(Cycle&& cycle, const std::atomic<bool>& stop, std::uint64_t max_cycles,
                     LoopStatistics& stats);

  [[nodiscard]] std::chrono::nanoseconds period() const { return period_; }

 private:
  static hal::Timestamp monotonic_now() { return clock_.now(); }
  static void sleep_until(hal::Timestamp t);

  inline static const hal::MonotonicClock clock_{};
  std::chrono::nanoseconds period_;
};

inline void RealTimeRunner::sleep_until(hal::Timestamp t) {
  timespec ts{};
  ts.tv_sec = static_cast<time_t>(t.count() / 1'000'000'000);
  ts.tv_nsec = static_cast<long>(t.count() % 1'000'000'000);
  // EINTR (a signal) just sleeps again towards the same absolute time.
  while (clock_nanosleep(CLOCK_MONOTONIC, TIMER_ABSTIME, &ts, nullptr) != 0) {
  }
}

template <typename Cycle>
hal::Timestamp RealTimeRunner::run(Cycle&& cycle, const std::atomic<bool>& stop,
                                   std::uint64_t max_cycles, LoopStatistics& stats) {
  // The first release is one period ahead, on a whole-period grid.
  hal::Timestamp release = (monotonic_now() / period_ + 1) * period_;
  for (std::uint64_t n = 0; (max_cycles == 0 || n < max_cycles) &&
                            !stop.load(std::memory_order_relaxed);
       ++n) {
    sleep_until(release);
    const hal::Timestamp woke = monotonic_now();
    cycle(release);
    const hal::Timestamp done = monotonic_now();
    stats.wake_latency.record((woke - release).count());
    stats.execution.record((done - woke).count());
    const auto elapsed = done - release;
    const std::uint64_t missed =
        elapsed > period_ ? static_cast<std::uint64_t>((elapsed + period_ - std::chrono::nanoseconds{1}) / period_) - 1
                          : 0u;
    stats.add_cycle(missed);
    release += static_cast<std::int64_t>(missed + 1) * period_;
  }
  return release;
}

}  // namespace mrd::runtime
