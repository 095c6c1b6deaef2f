#pragma once

#include <cstdint>
#include <optional>

#include "hal/clock.hpp"
#include "hal/current_driver.hpp"
#include "hal/mock/fault_script.hpp"

namespace mrd::hal::mock {

// A driver that follows its setpoint exactly and at once, unless the script adds a bias, makes
// writes fail or be refused, or silences the readback.
class MockCurrentDriver final : public CurrentDriver {
 public:
  MockCurrentDriver(const Clock& clock, const FaultScript& script)
      : clock_(clock), script_(script) {}

  IoStatus write_setpoint(double amps) override;
  [[nodiscard]] std::optional<CurrentReading> measured() override;
  [[nodiscard]] SetpointAcks setpoint_acks() const override { return acks_; }

  [[nodiscard]] double last_setpoint() const { return setpoint_; }
  [[nodiscard]] std::uint64_t writes() const { return writes_; }
  [[nodiscard]] std::uint64_t failed_writes() const { return failed_writes_; }

 private:
  const Clock& clock_;
  const FaultScript& script_;
  double setpoint_ = 0.0;  // A; the driver idles at zero
  std::uint64_t writes_ = 0;
  std::uint64_t failed_writes_ = 0;
  SetpointAcks acks_;
};

}  // namespace mrd::hal::mock
