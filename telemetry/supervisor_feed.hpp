#pragma once

#include <atomic>
#include <boost/lockfree/spsc_queue.hpp>
#include <cstddef>
#include <cstdint>

#include "common/single_writer_counter.hpp"
#include "control/supervisor.hpp"
#include "hal/clock.hpp"
#include "telemetry/telemetry_record.hpp"

namespace mrd::telemetry {

// One supervisor transition, as the real-time thread saw it.
struct SupervisorEvent {
  std::uint64_t cycle = 0;
  hal::Timestamp time{};  // the cycle's release time
  control::SupervisorState from = control::SupervisorState::kInit;
  control::SupervisorState to = control::SupervisorState::kInit;
  control::Trigger trigger = control::Trigger::kNone;
};

// What the real-time thread tells the others about the supervisor, and the only way they
// learn it: the state as a single-writer snapshot (an atomic the loop stores once a cycle) and
// each transition as an event in a lock-free SPSC ring that one non-real-time thread drains
// into the journal. The loop never blocks on it and never allocates: a full ring drops the
// event and counts it. Nothing here reads the supervisor object from another thread.
class SupervisorFeed {
 public:
  static constexpr std::size_t kCapacity = 256;  // a flapping fault at 1 kHz for 100 ms

  // Loop thread, after every cycle, with the record that cycle produced.
  void publish(const TelemetryRecord& r) noexcept {
    const auto to = static_cast<control::SupervisorState>(r.state);
    const auto why = static_cast<control::Trigger>(r.trigger);
    if (why != control::Trigger::kNone) {
      if (!ring_.push(SupervisorEvent{r.cycle, r.time, last_, to, why})) lost_.add();
    }
    // What put the loop into SAFE, kept while it stays there: the exit status of a run that ends
    // in SAFE through a fault rather than through the stop request.
    if (to != control::SupervisorState::kSafe) {
      safe_cause_.store(static_cast<std::uint8_t>(control::Trigger::kNone), std::memory_order_relaxed);
    } else if (last_ != control::SupervisorState::kSafe) {
      safe_cause_.store(static_cast<std::uint8_t>(why), std::memory_order_relaxed);
    }
    last_ = to;
    if (r.force_scale_at_bound) {
      scale_at_bound_.store(r.force_scale, std::memory_order_relaxed);
      // The count is published after the scale (release): a reader that sees the new count
      // (acquire) sees this scale. One writer: a load and a store, no locked add.
      scale_bound_hits_.store(scale_bound_hits_.load(std::memory_order_relaxed) + 1, std::memory_order_release);
    }
    state_.store(r.state, std::memory_order_release);
    latched_.store(r.latched, std::memory_order_release);
  }

  // Any thread: the state after the newest published cycle.
  [[nodiscard]] control::SupervisorState state() const {
    return static_cast<control::SupervisorState>(state_.load(std::memory_order_acquire));
  }
  // Any thread: whether that state is a SAFE only an operator's clear (SIGUSR2) ends.
  [[nodiscard]] bool latched() const { return latched_.load(std::memory_order_acquire); }
  // Any thread: how often force mode's load-cell correction took the scale onto a bound, and
  // the scale it was held at the last time (for the journal line).
  [[nodiscard]] std::uint64_t force_scale_bound_hits() const {
    return scale_bound_hits_.load(std::memory_order_acquire);  // pairs with publish(): the scale read next
  }
  // Read after force_scale_bound_hits(): at least as new as the hit that count includes.
  [[nodiscard]] double force_scale_at_bound() const { return scale_at_bound_.load(std::memory_order_relaxed); }
  // Any thread: the trigger that took the loop into the SAFE it is in (kNone when not in SAFE).
  [[nodiscard]] control::Trigger safe_cause() const {
    return static_cast<control::Trigger>(safe_cause_.load(std::memory_order_relaxed));
  }
  // Any thread: transitions the ring had no room for.
  [[nodiscard]] std::uint64_t lost() const { return lost_.get(); }

  // The one consumer thread: hands every queued event to `sink`, oldest first.
  template <typename Sink>
  std::size_t drain(Sink&& sink) {
    return ring_.consume_all(sink);
  }

 private:
  boost::lockfree::spsc_queue<SupervisorEvent, boost::lockfree::capacity<kCapacity>> ring_;
  std::atomic<std::uint8_t> state_{static_cast<std::uint8_t>(control::SupervisorState::kInit)};
  std::atomic<bool> latched_{false};
  std::atomic<std::uint8_t> safe_cause_{static_cast<std::uint8_t>(control::Trigger::kNone)};
  static_assert(std::atomic<std::uint8_t>::is_always_lock_free, "the loop publishes the state without a lock");
  control::SupervisorState last_ = control::SupervisorState::kInit;  // loop thread only
  SingleWriterCounter lost_;
  std::atomic<std::uint64_t> scale_bound_hits_{0};
  std::atomic<double> scale_at_bound_{1.0};
  static_assert(std::atomic<double>::is_always_lock_free, "the loop publishes the scale without a lock");
};

}  // namespace mrd::telemetry
