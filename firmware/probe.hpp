#pragma once

#include <cstdint>
#include <cstdio>
#include <optional>
#include <string>
#include <vector>

#include "config/controller_config.hpp"
#include "firmware/hal_devices.hpp"
#include "hal/clock.hpp"
#include "hal/current_driver.hpp"
#include "hal/sample.hpp"

namespace mrd::firmware {

// What commissioning expects of the buses, from the config.
struct ProbeExpectations {
  double displacement_min = -0.050;  // [m] safety.displacement_min..max: a reading outside
  double displacement_max = 0.050;   //     points at a wrong scale, offset or word order
  bool current_feedback = true;      // the driver reports its current (Modbus/CAN config)
  double current_tolerance = 0.1;    // [A] more than this with the enable low is wrong
  std::uint64_t min_samples = 5;     // usable LVDT samples the window must bring

  static ProbeExpectations from(const config::ControllerConfig& config);
};

// One poll of the devices.
struct ProbeReading {
  hal::Timestamp time{};
  std::optional<hal::Sample> lvdt;  // [m]
  std::optional<hal::CurrentReading> current;
  std::optional<bool> fault;  // nullopt: the fault line could not be read
};

// mrd-controller --probe: the buses opened with the driver held off (the enable line low, and
// no setpoint ever written), a few readings decoded, and a verdict. Time comes in as an
// argument, so tests script it on the mock HAL.
class Probe {
 public:
  Probe(HalDevices devices, const ProbeExpectations& expect) : hal_(devices), expect_(expect) {}

  // Drives the enable line low. The probe writes nothing else.
  void disable_driver();
  ProbeReading poll(hal::Timestamp now);

  // "" when the buses work as configured, else one problem per line.
  [[nodiscard]] std::string problems() const;
  [[nodiscard]] std::string summary() const;  // counts and ranges, one line per device
  [[nodiscard]] static std::string format(const ProbeReading& r, hal::Timestamp start);

 private:
  struct Range {
    double min = 0.0;
    double max = 0.0;
    std::uint64_t count = 0;
    void add(double v);
  };

  HalDevices hal_;
  ProbeExpectations expect_;
  bool enable_failed_ = false;
  std::uint64_t polls_ = 0;
  std::uint64_t samples_ = 0;       // every LVDT sample, usable or not
  std::uint64_t unusable_ = 0;      // not valid, corrupted or a sensor fault
  std::uint64_t not_finite_ = 0;
  Range lvdt_;                      // usable, finite samples [m]
  Range current_;                   // [A]
  std::uint64_t fault_set_ = 0;
  std::uint64_t fault_unreadable_ = 0;
};

struct ProbeOptions {
  double window_s = 1.0;    // how long to read
  double interval_s = 0.01; // between two polls
  int print_readings = 5;   // the first readings, decoded
};

// The whole probe on the configured back ends: 0 when every check passed, 1 when a back end
// could not start, 2 when the readings are wrong; what failed is printed.
int run_probe(const config::ControllerConfig& config, const ProbeOptions& options, std::FILE* out);

}  // namespace mrd::firmware
