#pragma once

#include <chrono>
#include <cstdint>
#include <optional>
#include <string_view>

#include "control/control_law.hpp"
#include "runtime/rt_setup.hpp"
#include "control/supervisor.hpp"
#include "telemetry/telemetry_config.hpp"
#include "hal/can/socketcan_config.hpp"
#include "hal/gpio/gpio_config.hpp"
#include "hal/modbus/modbus_config.hpp"

namespace mrd::config {

enum class DeviceBackend : std::uint8_t { kMock, kModbus, kCan };  // LVDT and current driver
enum class LinesBackend : std::uint8_t { kMock, kGpio };
[[nodiscard]] std::string_view to_string(DeviceBackend b);
[[nodiscard]] std::string_view to_string(LinesBackend b);

struct BackendSelection {
  DeviceBackend lvdt = DeviceBackend::kMock;
  DeviceBackend driver = DeviceBackend::kMock;
  LinesBackend lines = LinesBackend::kMock;
  std::optional<DeviceBackend> demand;  // the force demand; set in force mode only
  std::optional<DeviceBackend> load_cell;  // force mode's optional load cell (none: open-loop on the model)

  [[nodiscard]] bool uses(DeviceBackend b) const {
    return lvdt == b || driver == b || demand == b || load_cell == b;
  }
  [[nodiscard]] bool any_mock() const {
    return uses(DeviceBackend::kMock) || lines == LinesBackend::kMock;
  }
};

// The in-process simulated rig that moves the mock LVDT: a sine like the paper's Table 4 test
// through the simulated damper (sim/DamperPlant, the default damper's physics).
struct SimulationConfig {
  double amplitude = 0.040;   // [m]
  double frequency = 0.5;     // [Hz]
  double lvdt_noise = 5e-6;   // RMS [m]
  std::uint32_t seed = 1;
  // Force mode with the mock demand: the outer controller asks for c v on the sine's velocity,
  // a dissipative demand (docs/FORCE-CONTROL.md).
  double demand_damping = 250e3;  // [N s/m]

  [[nodiscard]] ValidationReport validate() const;  // field paths relative to [simulation]
};

// Everything mrd-controller reads from its TOML file, in SI units.
struct ControllerConfig {
  double rate = 1000.0;  // [Hz]; sets law.observer.sample_period
  BackendSelection backends;
  SimulationConfig simulation;
  hal::modbus::ModbusConfig modbus;
  hal::can::SocketCanConfig can;
  hal::gpio::GpioConfig gpio;
  control::ControlLawConfig law;
  control::SupervisorConfig safety;
  runtime::RealtimeConfig realtime;
  telemetry::TelemetryConfig telemetry;

  [[nodiscard]] std::chrono::nanoseconds period() const {
    return std::chrono::nanoseconds{static_cast<std::int64_t>(1e9 / rate + 0.5)};
  }
};

}  // namespace mrd::config
