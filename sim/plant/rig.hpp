#pragma once

#include <array>
#include <optional>
#include <vector>

#include "sim/damper_plant.hpp"
#include "sim/displacement_profile.hpp"
#include "sim/plant/plant_config.hpp"

namespace mrd::plant {

// The faults in force at one instant, with their values.
struct ActiveFaults {
  static constexpr std::size_t kKinds = static_cast<std::size_t>(FaultKind::kCount);
  std::array<bool, kKinds> on{};
  std::array<double, kKinds> value{};

  [[nodiscard]] bool has(FaultKind k) const { return on[static_cast<std::size_t>(k)]; }
  [[nodiscard]] double value_of(FaultKind k) const { return value[static_cast<std::size_t>(k)]; }
};
// Overlapping faults of one kind: the later one in the file sets the value.
[[nodiscard]] ActiveFaults active_faults(const std::vector<Fault>& faults, double t);

using Motion = sim::DisplacementProfile;
// Builds the profile; playback reads its file (throws record::InputError when it is bad).
[[nodiscard]] Motion make_motion(const PlantConfig& config);

// What the rig's sensors put on its buses in one period.
struct SensorReadings {
  double lvdt;                   // [m], after the LVDT faults
  double coil_current;           // [A], the driver's feedback
  std::optional<double> demand;  // [N], force mode's outer controller; none when the plant is not it
};

// One period of the rig: the plant time, the fault clock and the driver's setpoint.
struct RigInput {
  double t;          // [s] since the start
  double fault_t;    // [s] on the fault clock; < 0: no fault yet
  double commanded;  // [A], the setpoint the driver holds (0 when it is disabled)
};

// One plant step: what happened and what the LVDT reports.
struct RigSample {
  double time = 0.0;           // [s] since the start
  double fault_time = -1.0;    // [s] on the fault clock; < 0 before it starts
  sim::PlantReading reading;   // the truth
  double lvdt = 0.0;           // what the LVDT reports, after the LVDT faults [m]
  double commanded = 0.0;      // the coil current the driver was told [A]
  ActiveFaults faults;
};

// The rig without buses: motion, damper, LVDT faults, one step per period. Pure apart from
// the noise streams: the caller gives the time and the command, so tests drive it by hand.
class Rig {
 public:
  Rig(const PlantConfig& config, Motion motion);

  const RigSample& step(const RigInput& in);
  [[nodiscard]] const RigSample& last() const { return last_; }

 private:
  Motion motion_;
  sim::DamperPlant plant_;
  std::vector<Fault> faults_;
  std::optional<double> frozen_;
  RigSample last_;
};

}  // namespace mrd::plant
