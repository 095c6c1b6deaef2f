#pragma once

#include <chrono>

namespace mrd::hal {

using Timestamp = std::chrono::nanoseconds;  // since an arbitrary, monotonic epoch

// Time is injected: the loop and the supervisor ask a Clock, so tests drive time by hand.
class Clock {
 public:
  virtual ~Clock() = default;
  [[nodiscard]] virtual Timestamp now() const = 0;
};

// CLOCK_MONOTONIC, the clock the real-time loop sleeps on.
class MonotonicClock final : public Clock {
 public:
  [[nodiscard]] Timestamp now() const override;
};

// A clock that moves only when told to: deterministic tests never sleep.
class ManualClock final : public Clock {
 public:
  explicit ManualClock(Timestamp start = Timestamp{0}) : now_(start) {}
  [[nodiscard]] Timestamp now() const override { return now_; }
  void advance(Timestamp by) { now_ += by; }
  void set(Timestamp to) { now_ = to; }

 private:
  Timestamp now_;
};

}  // namespace mrd::hal
