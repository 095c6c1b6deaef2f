#include "hal/gpio/gpio_config.hpp"

namespace mrd::hal::gpio {

ValidationReport GpioConfig::validate() const {
  ValidationReport r;
  r.check(!chip.empty(), "chip", "must name a GPIO chip (gpiochip0, /dev/gpiochip0, a label)");
  r.check(enable.offset >= 0, "enable.offset", "must be >= 0");
  r.check(fault.offset >= 0, "fault.offset", "must be >= 0");
  r.check(heartbeat.offset >= 0, "heartbeat.offset", "must be >= 0");
  r.check(fault.offset != enable.offset, "fault.offset", "must differ from enable.offset");
  r.check(heartbeat.offset != enable.offset && heartbeat.offset != fault.offset,
          "heartbeat.offset", "must differ from enable.offset and fault.offset");
  // The kernel keeps 31 characters of a consumer label; "-heartbeat" takes 10.
  r.check(!consumer_prefix.empty() && consumer_prefix.size() <= 21, "consumer_prefix",
          "must be 1..21 characters");
  return r;
}

}  // namespace mrd::hal::gpio
