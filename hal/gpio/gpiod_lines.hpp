#pragma once

#include <gpiod.hpp>

#include <atomic>
#include <cstdint>
#include <optional>
#include <vector>

#include "hal/digital_lines.hpp"
#include "hal/gpio/gpio_config.hpp"
#include "hal/status.hpp"

namespace mrd::hal::gpio {

// Driver enable, driver fault and heartbeat on GPIO lines through libgpiod 1.6's C++ API
// (Debian 12's libgpiodcxx). libgpiodcxx throws: start() turns that into an error string, and
// every hot-path call catches and returns a status instead.
//
// Allocation: libgpiodcxx 1.6's line::set_value/get_value build a line_bulk (a std::vector)
// on every call. So outputs are written through a line_bulk and a value vector built once at
// start, and the fault input is requested for edge events: driver_fault() drains the event fd
// with poll() and event_read(), neither of which allocates.
class GpiodLines final : public DigitalLines {
 public:
  explicit GpiodLines(GpioConfig config) : config_(std::move(config)) {}
  ~GpiodLines() override;  // drives enable inactive before the lines are released
  GpiodLines(const GpiodLines&) = delete;
  GpiodLines& operator=(const GpiodLines&) = delete;

  // Opens the chip and requests the lines; outputs start inactive (driver disabled).
  [[nodiscard]] StartResult start();

  IoStatus set_enable(bool enabled) override;
  // nullopt before start() or when the line cannot be read.
  [[nodiscard]] std::optional<bool> driver_fault() override;

  [[nodiscard]] std::uint64_t io_errors() const { return io_errors_.load(std::memory_order_relaxed); }

 protected:
  IoStatus write_heartbeat(bool high) override;

 private:
  struct Output {
    gpiod::line_bulk bulk;
    std::vector<int> value = std::vector<int>(1, 0);
  };
  IoStatus write(Output& out, bool active) noexcept;
  std::nullopt_t io_error() noexcept;  // counts one failed call
  void release_all() noexcept;

  GpioConfig config_;
  gpiod::chip chip_;
  Output enable_;
  Output heartbeat_;
  gpiod::line fault_;
  int fault_fd_ = -1;
  bool fault_active_ = false;
  bool started_ = false;
  std::atomic<std::uint64_t> io_errors_{0};
};

}  // namespace mrd::hal::gpio
