#pragma once

#include <string>
#include <string_view>

#include "common/validation_report.hpp"

namespace mrd::hal::gpio {

struct GpioLineConfig {
  int offset = 0;           // line offset on the chip
  bool active_low = false;  // true when the logical "on" is the low level on the pin
};

struct GpioConfig {
  // Anything libgpiod's lookup accepts: "gpiochip0", "/dev/gpiochip0", a chip label, or "0".
  std::string chip = "gpiochip0";
  GpioLineConfig enable{0, false};     // out: driver enable
  GpioLineConfig fault{1, false};      // in: driver fault
  GpioLineConfig heartbeat{2, false};  // out: watchdog heartbeat
  std::string consumer_prefix = "mrd";  // lines show as "mrd-enable" etc. in gpioinfo

  [[nodiscard]] std::string consumer(std::string_view role) const {
    return consumer_prefix + "-" + std::string(role);
  }
  [[nodiscard]] ValidationReport validate() const;  // field paths relative to the gpio table
};

}  // namespace mrd::hal::gpio
