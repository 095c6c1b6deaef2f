#pragma once

#include "hal/clock.hpp"
#include "hal/mock/fault_script.hpp"
#include "hal/mock/mock_current_driver.hpp"
#include "hal/mock/mock_digital_lines.hpp"
#include "hal/mock/mock_sample_source.hpp"

namespace mrd::hal::mock {

// The whole mock HAL on one manual clock: a drop-in for the real back ends in loop tests.
// Not copyable or movable: the devices hold references to the clock and the script.
struct MockHal {
  explicit MockHal(FaultScript fault_script = {}, Timestamp start = Timestamp{0})
      : clock(start), script(std::move(fault_script)) {}
  MockHal(const MockHal&) = delete;
  MockHal& operator=(const MockHal&) = delete;

  ManualClock clock;
  FaultScript script;
  MockSampleSource lvdt{clock, script, kLvdtFaults};  // displacement [m]
  MockCurrentDriver driver{clock, script};
  MockDigitalLines lines{clock, script};
  MockSampleSource demand{clock, script, kDemandFaults};  // force mode's demand [N]
  MockSampleSource load_cell{clock, script, {}};  // force mode's optional load cell [N]: no script faults
};

}  // namespace mrd::hal::mock
