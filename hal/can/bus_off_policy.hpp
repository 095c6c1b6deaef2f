#pragma once

#include <chrono>
#include <cstdint>

#include "hal/can/can_error.hpp"
#include "hal/clock.hpp"

namespace mrd::hal::can {

// What we do when our controller goes bus-off. We run unprivileged (no CAP_NET_ADMIN), so we
// cannot restart the interface ourselves: the interface must be set up with the kernel's
// automatic restart (`ip link set can0 type can restart-ms 100`). Policy, after CANopenNode:
//   1. bus-off: stop transmitting at once and count the event;
//   2. the controller is back when the kernel reports "restarted", or when a good frame
//      arrives (some drivers send no restart frame);
//   3. listen only for `hold_off`, then transmit again. A new bus-off restarts from 1.
// Pure and time-injected, so the policy is tested without a bus.
class BusOffPolicy {
 public:
  enum class State : std::uint8_t { kActive, kBusOff, kHoldOff };

  explicit BusOffPolicy(Timestamp hold_off) : hold_off_(hold_off) {}

  void on_error(const CanErrorEvent& e, Timestamp now);
  void on_good_frame(Timestamp now);

  [[nodiscard]] State state(Timestamp now) const;
  [[nodiscard]] bool tx_allowed(Timestamp now) const { return now >= tx_allowed_from_; }
  // Timestamp::max() while bus-off: what the back end publishes to the transmit path.
  [[nodiscard]] Timestamp tx_allowed_from() const { return tx_allowed_from_; }
  [[nodiscard]] std::uint64_t bus_off_events() const { return bus_off_events_; }

 private:
  void back_on_bus(Timestamp now);

  Timestamp hold_off_;
  Timestamp tx_allowed_from_ = Timestamp::min();
  bool bus_off_ = false;
  std::uint64_t bus_off_events_ = 0;
};

}  // namespace mrd::hal::can
