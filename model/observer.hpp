#pragma once

#include "model/bingham_damper.hpp"
#include "model/damper_model.hpp"
#include "model/effects/effect_chain.hpp"
#include "model/jiles_atherton.hpp"
#include "model/mr_fluid.hpp"
#include "model/velocity_filter.hpp"

namespace mrd::model {

struct ObserverSettings {
  double sample_period = 1e-3;          // [s]
  double velocity_cutoff_frequency = 20.0;  // [Hz], used only without a velocity sensor
};

// When a displacement sample was taken, on the loop's clock: an LVDT read over a bus delivers
// its samples at the bus's pace, not the loop's.
struct SampleTiming {
  bool fresh = true;      // a new sample, not one held from an earlier period
  double interval = 0.0;  // [s] since the previous new sample
  double age = 0.0;       // [s] from the sample to this step
};

struct ObserverEstimate {
  double B = 0.0;             // gap induction [T]
  double yield_stress = 0.0;  // [Pa], after the thermal factor when thermal_drift is on
  double velocity = 0.0;      // measured or filtered [m/s], predicted when sensor_delay is on
  double force = 0.0;         // predicted damper force [N]
};

// The J-A + Bingham observer of Fig. 5: coil current -> B (Eq. 1-10) -> tau_y (Eq. 13)
// -> force with the piston velocity (Eq. 11-12). One step per control period; no heap.
// The model's optional effects (DamperModel::effects) run inside the step in the order
// EffectChain documents; with all of them off the step is the base model, bit for bit.
class Observer {
 public:
  Observer(const DamperModel& model, const ObserverSettings& settings = {});

  // Displacement only, one sample a period: velocity comes from the VelocityFilter.
  ObserverEstimate step(double displacement, double coil_current);
  // Displacement only, at its own timing: the VelocityFilter tracks each new sample at its real
  // interval and the velocity is carried to this step by the sample's age (at most two
  // periods, so that a silent sensor cannot extrapolate far).
  ObserverEstimate step(double displacement, const SampleTiming& timing, double coil_current);
  // With a velocity sensor.
  ObserverEstimate step(double displacement, double velocity, double coil_current);
  // With the gap induction B [T] known instead of the current: Eq. 13 and 11-12 and the effects
  // that act after B. For a damper with a field probe in its gap, and for fits that vary only
  // what acts after B and so can reuse one J-A run's B (tools/residual). The J-A state and the
  // coil lag are left as they are.
  ObserverEstimate step_at_induction(double displacement, double velocity, double B);

  // A measured fluid temperature [degC] for thermal_drift (NaN: back to its lumped model).
  void set_measured_temperature(double celsius) { effects_.set_measured_temperature(celsius); }

  [[nodiscard]] const JilesAtherton& magnetics() const { return magnetics_; }
  [[nodiscard]] const ObserverEstimate& estimate() const { return estimate_; }
  [[nodiscard]] const BinghamDamper& damper() const { return damper_; }
  [[nodiscard]] const YieldStress& yield_stress() const { return yield_stress_; }
  [[nodiscard]] const EffectChain& effects() const { return effects_; }
  void reset();

 private:
  // The step with at least one effect on. `filtered` says whether the velocity filter has
  // already seen this displacement (the displacement-only path).
  ObserverEstimate step_with_effects(double displacement, double velocity, double coil_current,
                                     bool filtered);
  // The motion the effects see: sensor_delay's prediction, or the reading.
  PredictedMotion motion_now(double displacement, double velocity, bool filtered);
  // Everything after B with every effect off (Eq. 13, 11-12).
  ObserverEstimate base_force(double velocity, double B);
  // Everything after B with at least one effect on.
  ObserverEstimate force_with_effects(const PredictedMotion& now, double B);

  double sample_period_;  // [s]
  JilesAtherton magnetics_;
  YieldStress yield_stress_;
  BinghamDamper damper_;
  VelocityFilter velocity_filter_;
  EffectChain effects_;
  ObserverEstimate estimate_;
};

}  // namespace mrd::model
