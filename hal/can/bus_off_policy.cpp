#include "hal/can/bus_off_policy.hpp"

namespace mrd::hal::can {

void BusOffPolicy::on_error(const CanErrorEvent& e, Timestamp now) {
  if (e.has(kErrBusOff)) {
    if (!bus_off_) ++bus_off_events_;
    bus_off_ = true;
    tx_allowed_from_ = Timestamp::max();
    return;
  }
  if (e.has(kErrRestarted)) back_on_bus(now);
}

void BusOffPolicy::on_good_frame(Timestamp now) { back_on_bus(now); }

void BusOffPolicy::back_on_bus(Timestamp now) {
  if (!bus_off_) return;
  bus_off_ = false;
  tx_allowed_from_ = now + hold_off_;
}

BusOffPolicy::State BusOffPolicy::state(Timestamp now) const {
  if (bus_off_) return State::kBusOff;
  return tx_allowed(now) ? State::kActive : State::kHoldOff;
}

}  // namespace mrd::hal::can
