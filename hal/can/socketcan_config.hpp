#pragma once

#include <chrono>
#include <cstdint>
#include <string>

#include "hal/can/can_codec.hpp"
#include "common/validation_report.hpp"

namespace mrd::hal::can {

struct SocketCanConfig {
  std::string interface = "can0";  // "vcan0" in the hardware-in-the-loop tests
  bool extended_ids = false;       // 29-bit ids instead of 11-bit
  std::uint32_t lvdt_id = kDefaultLvdtId;
  std::uint32_t command_id = kDefaultCommandId;
  bool use_feedback = true;  // the driver sends Coil_CurrentFeedback
  std::uint32_t feedback_id = kDefaultFeedbackId;
  // Force mode's Force_Demand frame. use_demand is not a file key: the loader sets it when
  // backends.demand = "can" (and only then is demand_id received and checked).
  bool use_demand = false;
  std::uint32_t demand_id = kDefaultDemandId;
  // Force mode's optional Load_Cell frame. use_load_cell is set by the loader for
  // backends.load_cell = "can", as use_demand is.
  bool use_load_cell = false;
  std::uint32_t load_cell_id = kDefaultLoadCellId;
  // SO_RCVTIMEO: the receive thread's longest block, so stop() returns within it.
  std::chrono::milliseconds receive_timeout{50};
  // Listen-only time after the controller is back from bus-off (see BusOffPolicy).
  std::chrono::milliseconds bus_off_hold_off{500};

  [[nodiscard]] ValidationReport validate() const;  // field paths relative to the can table
};

}  // namespace mrd::hal::can
