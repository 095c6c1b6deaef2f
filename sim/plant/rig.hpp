#pragma once

#include <array>
#include <optional>
#include <variant>
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

using Motion = std::variant<sim::SineProfile, sim::SineSequenceProfile, sim::RandomProfile,
                            sim::PlaybackProfile>;
// Builds the profile; playback reads its file (throws record::InputError when it is bad).
[[nodiscard]] Motion make_motion(const PlantConfig& config);
// [s]; 0 for an endless profile (sine).
[[nodiscard]] double motion_length(const Motion& motion);

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

  // At plant time t and fault time fault_t (< 0: no fault yet); `commanded` is the setpoint
  // the driver holds this period (0 when it is disabled).
  const RigSample& step(double t, double fault_t, double commanded);
  [[nodiscard]] const RigSample& last() const { return last_; }

 private:
  Motion motion_;
  sim::DamperPlant plant_;
  std::vector<Fault> faults_;
  std::optional<double> frozen_;
  RigSample last_;
};

}  // namespace mrd::plant
