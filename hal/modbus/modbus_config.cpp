#include "hal/modbus/modbus_config.hpp"

#include <chrono>

namespace mrd::hal::modbus {

namespace {

constexpr int kMaxAddress = 0xFFFF;

void check_address(ValidationReport& r, std::string_view field, int address, const RegisterFormat& f) {
  const int last = address + static_cast<int>(word_count(f.type)) - 1;
  r.check(address >= 0 && last <= kMaxAddress, field, "must be in 0..65535 (all words of the value)");
}

}  // namespace

ValidationReport RegisterMap::validate() const {
  ValidationReport r;
  check_address(r, "lvdt_address", lvdt_address, lvdt);
  r.merge(lvdt.validate(), "lvdt");
  check_address(r, "setpoint_address", setpoint_address, setpoint);
  r.merge(setpoint.validate(), "setpoint");
  if (has_current_feedback) {
    check_address(r, "current_feedback_address", current_feedback_address, current_feedback);
    r.merge(current_feedback.validate(), "current_feedback");
  }
  if (has_demand) {
    check_address(r, "demand_address", demand_address, demand);
    r.merge(demand.validate(), "demand");
    r.check(demand_counter_address >= -1 && demand_counter_address <= kMaxAddress, "demand_counter_address",
            "must be -1 (none) or in 0..65535");
  }
  if (has_load_cell) {
    check_address(r, "load_cell_address", load_cell_address, load_cell);
    r.merge(load_cell.validate(), "load_cell");
  }
  return r;
}

ValidationReport ModbusConfig::validate() const {
  using namespace std::chrono_literals;
  ValidationReport r;
  if (transport == Transport::kTcp) {
    r.check(!tcp.host.empty(), "tcp.host", "must not be empty");
    r.check(tcp.port >= 1 && tcp.port <= 65535, "tcp.port", "must be in 1..65535");
  } else {
    r.check(!rtu.device.empty(), "rtu.device", "must not be empty");
    r.check(rtu.baud > 0, "rtu.baud", "must be > 0");
    r.check(rtu.parity == 'N' || rtu.parity == 'E' || rtu.parity == 'O', "rtu.parity",
            "must be N, E or O");
    r.check(rtu.data_bits >= 5 && rtu.data_bits <= 8, "rtu.data_bits", "must be in 5..8");
    r.check(rtu.stop_bits == 1 || rtu.stop_bits == 2, "rtu.stop_bits", "must be 1 or 2");
  }
  // 0 is broadcast (no reply), 248..255 are reserved; TCP gateways also use 255.
  r.check((slave_id >= 1 && slave_id <= 247) || (transport == Transport::kTcp && slave_id == 255),
          "slave_id", "must be in 1..247 (or 255 over TCP)");
  r.check(response_timeout > 0us, "response_timeout", "must be > 0");
  r.check(byte_timeout >= 0us, "byte_timeout", "must be >= 0");
  r.check(poll_period > 0us, "poll_period", "must be > 0");
  if (r.check(reconnect_min > 0ms, "reconnect_min", "must be > 0")) {
    r.check(reconnect_max >= reconnect_min, "reconnect_max", "must be >= reconnect_min");
  }
  r.merge(registers.validate(), "registers");
  return r;
}

}  // namespace mrd::hal::modbus
