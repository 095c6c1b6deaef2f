#pragma once

#include <span>

#include "hal/current_driver.hpp"
#include "hal/demand_source.hpp"
#include "hal/digital_lines.hpp"
#include "hal/displacement_source.hpp"
#include "hal/io_thread.hpp"
#include "hal/load_cell_source.hpp"

namespace mrd::firmware {

// The devices one control loop talks to, whichever back ends provide them.
struct HalDevices {
  hal::DisplacementSource& lvdt;
  hal::CurrentDriver& driver;
  hal::DigitalLines& lines;
  hal::DemandSource* demand = nullptr;  // the force demand; force mode needs it, table4 reads none
  hal::LoadCellSource* load_cell = nullptr;  // force mode's optional load cell
  std::span<hal::IoThread* const> io_threads{};  // the bus back ends' threads, watched for progress
};

}  // namespace mrd::firmware
