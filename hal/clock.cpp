#include "hal/clock.hpp"

#include <time.h>

namespace mrd::hal {

Timestamp MonotonicClock::now() const {
  timespec ts{};
  clock_gettime(CLOCK_MONOTONIC, &ts);
  return std::chrono::seconds{ts.tv_sec} + std::chrono::nanoseconds{ts.tv_nsec};
}

}  // namespace mrd::hal
