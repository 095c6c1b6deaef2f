#pragma once

#include <memory>
#include <string>
#include <vector>

#include "config/controller_config.hpp"
#include "firmware/hal_devices.hpp"
#include "hal/can/socketcan_backend.hpp"
#include "hal/clock.hpp"
#include "hal/gpio/gpiod_lines.hpp"
#include "hal/mock/mock_hal.hpp"
#include "hal/modbus/modbus_backend.hpp"
#include "hal/status.hpp"

namespace mrd::firmware {

// The back ends the config selects, built and owned in one place. A device on the mock picks
// the MockHal, whose manual clock the caller sets each cycle; the bus back ends timestamp on
// `clock`, which must be the loop's clock (CLOCK_MONOTONIC in the controller).
class HalSet {
 public:
  HalSet(const config::ControllerConfig& config, const hal::Clock& clock);
  ~HalSet();
  HalSet(const HalSet&) = delete;
  HalSet& operator=(const HalSet&) = delete;

  // Starts the bus back ends and the GPIO lines; the error names each one that failed.
  [[nodiscard]] hal::StartResult start();
  void stop();

  [[nodiscard]] HalDevices devices() { return {*lvdt_, *driver_, *lines_, demand_, load_cell_, threads_}; }
  [[nodiscard]] hal::mock::MockHal* mock() { return mock_.get(); }
  // The bus back ends, null where the config uses none of their devices.
  [[nodiscard]] hal::modbus::ModbusBackend* modbus() { return modbus_.get(); }
  [[nodiscard]] hal::can::SocketCanBackend* can() { return can_.get(); }
  // The bus back ends' I/O threads (running after start()), for the real-time set-up.
  [[nodiscard]] const std::vector<hal::IoThread*>& io_threads() const { return threads_; }
  // One line per bus back end with its counters, for the statistics printout.
  [[nodiscard]] std::string counters() const;
  // One line per bus whose link is down, with the endpoint and the system's reason (empty: none).
  [[nodiscard]] std::vector<std::string> link_problems() const;
  // Whether a bus link never came up at all (the probe's "bus cannot start").
  [[nodiscard]] bool link_never_up() const;

 private:
  class CanEnableLines;

  std::unique_ptr<hal::mock::MockHal> mock_;
  std::unique_ptr<hal::modbus::ModbusBackend> modbus_;
  std::unique_ptr<hal::can::SocketCanBackend> can_;
  std::unique_ptr<hal::gpio::GpiodLines> gpio_;
  std::unique_ptr<hal::DigitalLines> can_enable_;
  hal::SampleSource* lvdt_ = nullptr;
  hal::CurrentDriver* driver_ = nullptr;
  hal::DigitalLines* lines_ = nullptr;
  hal::SampleSource* demand_ = nullptr;     // force mode only
  hal::SampleSource* load_cell_ = nullptr;  // force mode with backends.load_cell only
  std::vector<hal::IoThread*> threads_;
  bool can_lvdt_ = false;      // which frames the CAN link should carry
  bool can_feedback_ = false;
};

}  // namespace mrd::firmware
