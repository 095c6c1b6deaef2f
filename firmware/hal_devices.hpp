#pragma once

#include "hal/current_driver.hpp"
#include "hal/digital_lines.hpp"
#include "hal/displacement_source.hpp"

namespace mrd::firmware {

// The three devices one control loop talks to, whichever back ends provide them.
struct HalDevices {
  hal::DisplacementSource& lvdt;
  hal::CurrentDriver& driver;
  hal::DigitalLines& lines;
};

}  // namespace mrd::firmware
