#pragma once

#include "hal/clock.hpp"
#include "hal/mock/fault_script.hpp"
#include "hal/mock/mock_current_driver.hpp"
#include "hal/mock/mock_demand_source.hpp"
#include "hal/mock/mock_digital_lines.hpp"
#include "hal/mock/mock_displacement_source.hpp"
#include "hal/mock/mock_load_cell_source.hpp"

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
  MockDisplacementSource lvdt{clock, script};
  MockCurrentDriver driver{clock, script};
  MockDigitalLines lines{clock, script};
  MockDemandSource demand{clock, script};  // force mode
  MockLoadCellSource load_cell{clock};     // force mode's optional load cell
};

}  // namespace mrd::hal::mock
