#pragma once

#include <span>

#include "hal/current_driver.hpp"
#include "hal/digital_lines.hpp"
#include "hal/io_thread.hpp"
#include "hal/sample_source.hpp"

namespace mrd::firmware {

// The devices one control loop talks to, whichever back ends provide them.
struct HalDevices {
  hal::SampleSource& lvdt;  // the damper's displacement [m]
  hal::CurrentDriver& driver;
  hal::DigitalLines& lines;
  // The force the outer controller (skyhook, clipped-optimal, LQG) demands of the damper [N],
  // with the sign of the motion it resists (docs/FORCE-CONTROL.md); force mode needs it, table4
  // reads none.
  hal::SampleSource* demand = nullptr;
  // The damper force a load cell in series with the damper measures [N], with the demand's sign
  // (docs/FORCE-CONTROL.md, "Load-cell feedback"); force mode's optional load cell.
  hal::SampleSource* load_cell = nullptr;
  std::span<hal::IoThread* const> io_threads{};  // the bus back ends' threads, watched for progress
};

}  // namespace mrd::firmware
