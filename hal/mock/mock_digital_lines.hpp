#pragma once

#include <cstdint>
#include <optional>

#include "hal/clock.hpp"
#include "hal/digital_lines.hpp"
#include "hal/mock/fault_script.hpp"

namespace mrd::hal::mock {

// Lines that record what the loop drives and report the scripted fault line.
class MockDigitalLines final : public DigitalLines {
 public:
  MockDigitalLines(const Clock& clock, const FaultScript& script)
      : clock_(clock), script_(script) {}

  IoStatus set_enable(bool enabled) override;
  [[nodiscard]] std::optional<bool> driver_fault() override;

  [[nodiscard]] bool enabled() const { return enabled_; }
  [[nodiscard]] std::uint64_t enable_transitions() const { return enable_transitions_; }
  [[nodiscard]] std::uint64_t heartbeat_toggles() const { return heartbeat_toggles_; }

 protected:
  IoStatus write_heartbeat(bool high) override;

 private:
  const Clock& clock_;
  const FaultScript& script_;
  bool enabled_ = false;
  bool heartbeat_level_ = false;
  std::uint64_t enable_transitions_ = 0;
  std::uint64_t heartbeat_toggles_ = 0;
};

}  // namespace mrd::hal::mock
