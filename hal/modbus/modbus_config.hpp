#pragma once

#include <chrono>
#include <cstdint>
#include <string>

#include "common/validation_report.hpp"
#include "hal/modbus/register_codec.hpp"

namespace mrd::hal::modbus {

enum class Transport : std::uint8_t { kTcp, kRtu };
enum class RegisterKind : std::uint8_t { kInput, kHolding };  // function codes 0x04 / 0x03

struct TcpConfig {
  std::string host = "127.0.0.1";
  int port = 502;
};

struct RtuConfig {
  std::string device = "/dev/ttyUSB0";
  int baud = 115200;
  char parity = 'N';  // 'N', 'E' or 'O'
  int data_bits = 8;  // 5..8
  int stop_bits = 1;  // 1 or 2
};

// Where the values live on the device. Addresses are 0-based protocol addresses.
struct RegisterMap {
  int lvdt_address = 0;
  RegisterKind lvdt_kind = RegisterKind::kInput;
  RegisterFormat lvdt{RegisterType::kInt32, WordOrder::kHighFirst, ByteOrder::kNormal, 1e-6, 0.0};

  int setpoint_address = 0;  // holding register(s), written with 0x06 (one word) or 0x10 (two)
  RegisterFormat setpoint{RegisterType::kInt16, WordOrder::kHighFirst, ByteOrder::kNormal, 1e-3,
                          0.0};

  bool has_current_feedback = false;  // the driver reports its measured current
  int current_feedback_address = 2;  // after the LVDT's two words (mrd.toml and docs say 2)
  RegisterKind current_feedback_kind = RegisterKind::kInput;
  RegisterFormat current_feedback{RegisterType::kInt16, WordOrder::kHighFirst, ByteOrder::kNormal,
                                  1e-3, 0.0};

  // Force mode's demand [N], which the outer controller writes into the device; read with the
  // LVDT each poll. has_demand is not a file key: the loader sets it for backends.demand =
  // "modbus". Holding registers 2-3 by default, past a one- or two-word setpoint at 0.
  bool has_demand = false;
  int demand_address = 2;
  RegisterKind demand_kind = RegisterKind::kHolding;
  RegisterFormat demand{RegisterType::kInt32, WordOrder::kHighFirst, ByteOrder::kNormal, 0.1, 0.0};  // 0.1 N/count
  // Optional: one 16-bit word, of demand_kind, that the outer controller increments with every
  // new demand. Without it a demand it stopped updating reads as fresh each poll; with it a
  // poll that finds the counter unchanged yields no demand, so silence shows as missing, then
  // stale. -1: none.
  int demand_counter_address = -1;

  [[nodiscard]] bool has_demand_counter() const { return has_demand && demand_counter_address >= 0; }

  // Force mode's optional load cell [N], the force the device measures; read with the LVDT each
  // poll. has_load_cell is set by the loader for backends.load_cell = "modbus". Input registers
  // 4-5 by default, past the LVDT's two words and the current feedback's one.
  bool has_load_cell = false;
  int load_cell_address = 4;
  RegisterKind load_cell_kind = RegisterKind::kInput;
  RegisterFormat load_cell{RegisterType::kInt32, WordOrder::kHighFirst, ByteOrder::kNormal, 0.1, 0.0};  // 0.1 N/count

  [[nodiscard]] ValidationReport validate() const;
};

struct ModbusConfig {
  Transport transport = Transport::kTcp;
  TcpConfig tcp;
  RtuConfig rtu;
  int slave_id = 1;

  // libmodbus waits 500 ms by default; a 1 kHz loop needs to know within a few periods.
  std::chrono::microseconds response_timeout{20'000};
  std::chrono::microseconds byte_timeout{5'000};  // RTU inter-character gap; 0 disables
  std::chrono::microseconds poll_period{1'000};
  // Reconnect back-off: doubles from min to max after each failed attempt, resets on success.
  std::chrono::milliseconds reconnect_min{10};
  std::chrono::milliseconds reconnect_max{1'000};

  RegisterMap registers;

  [[nodiscard]] ValidationReport validate() const;  // field paths relative to the modbus table
};

}  // namespace mrd::hal::modbus
