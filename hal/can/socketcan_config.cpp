#include "hal/can/socketcan_config.hpp"

#include <linux/can.h>
#include <net/if.h>

namespace mrd::hal::can {

ValidationReport SocketCanConfig::validate() const {
  using namespace std::chrono_literals;
  ValidationReport r;
  r.check(!interface.empty() && interface.size() < IFNAMSIZ, "interface",
          "must be a network interface name of 1..15 characters");
  const std::uint32_t max_id = extended_ids ? CAN_EFF_MASK : CAN_SFF_MASK;
  const std::string range = extended_ids ? "must fit 29 bits (0..0x1FFFFFFF)"
                                         : "must fit 11 bits (0..0x7FF); set extended_ids for more";
  r.check(lvdt_id <= max_id, "lvdt_id", range);
  r.check(command_id <= max_id, "command_id", range);
  r.check(lvdt_id != command_id, "command_id", "must differ from lvdt_id");
  if (use_feedback) {
    r.check(feedback_id <= max_id, "feedback_id", range);
    r.check(feedback_id != lvdt_id && feedback_id != command_id, "feedback_id",
            "must differ from lvdt_id and command_id");
  }
  if (use_demand) {
    r.check(demand_id <= max_id, "demand_id", range);
    r.check(demand_id != lvdt_id && demand_id != command_id && !(use_feedback && demand_id == feedback_id),
            "demand_id", "must differ from lvdt_id, command_id and feedback_id");
  }
  if (use_load_cell) {
    r.check(load_cell_id <= max_id, "load_cell_id", range);
    r.check(load_cell_id != lvdt_id && load_cell_id != command_id && !(use_feedback && load_cell_id == feedback_id) &&
                !(use_demand && load_cell_id == demand_id),
            "load_cell_id", "must differ from lvdt_id, command_id, feedback_id and demand_id");
  }
  r.check(receive_timeout > 0ms, "receive_timeout", "must be > 0");
  r.check(bus_off_hold_off >= 0ms, "bus_off_hold_off", "must be >= 0");
  return r;
}

}  // namespace mrd::hal::can
