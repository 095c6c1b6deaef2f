#pragma once

#include <optional>

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

// What the observer takes each period. Named fields, so that a swapped argument does not
// compile: observer.step({.displacement = x, .coil_current = i}).
struct Measurement {
  double displacement = 0.0;  // [m]
  // [m/s] from a velocity sensor; without one the observer tracks it from the displacement.
  std::optional<double> velocity;
  // The sample's own timing; without it the sample is fresh, one period after the last.
  std::optional<SampleTiming> timing;
  double coil_current = 0.0;  // [A], the current that flowed this period (measured, or the last command)
  // [s] since the previous step, for a run replayed at the times its samples were taken;
  // without it one sample period. The loop runs at its fixed rate and leaves it out.
  std::optional<double> step_duration;
};

struct ObserverEstimate {
  double B = 0.0;             // gap induction [T]
  double yield_stress = 0.0;  // [Pa], after the effects' factors
  double velocity = 0.0;      // measured or tracked [m/s], predicted when an effect predicts the motion
  double force = 0.0;         // predicted damper force [N]
};

// The J-A + Bingham observer of Fig. 5: coil current -> B (Eq. 1-10) -> tau_y (Eq. 13)
// -> force with the piston velocity (Eq. 11-12). One step per control period; no heap.
// The model's optional effects (DamperModel::effects) run inside the step in the order
// EffectChain documents; with all of them off the step is the base model, bit for bit.
class Observer {
 public:
  Observer(const DamperModel& model, const ObserverSettings& settings = {});

  // One period: the velocity (Measurement says where it comes from), B from the coil current,
  // the force.
  ObserverEstimate step(const Measurement& m);
  // The same with the gap induction B [T] known instead of the current (m.coil_current is not
  // used): Eq. 13 and 11-12 and the effects that act after B. For a damper with a field probe in
  // its gap, and for fits that vary only what acts after B and so reuse one J-A run's B
  // (tools/residual). The J-A state and the coil lag are left as they are.
  ObserverEstimate step_at_induction(const Measurement& m, double B);

  // A measured fluid temperature [degC] for the effects that use one (NaN: back to their model).
  void set_measured_temperature(double celsius) { effects_.set_measured_temperature(celsius); }
  // A factor on the yield stress of Eq. 13 (so on the yield force of Eq. 12), 1 by default:
  // force mode's load-cell correction of a drifting model (control::ForceScaleCorrection). The
  // force inverse reads it from here, so the law and the estimate agree.
  void set_yield_scale(double scale) { yield_scale_ = scale; }
  [[nodiscard]] double yield_scale() const { return yield_scale_; }

  [[nodiscard]] const JilesAtherton& magnetics() const { return magnetics_; }
  [[nodiscard]] const ObserverEstimate& estimate() const { return estimate_; }
  [[nodiscard]] const BinghamDamper& damper() const { return damper_; }
  [[nodiscard]] const YieldStress& yield_stress() const { return yield_stress_; }
  [[nodiscard]] const EffectChain& effects() const { return effects_; }
  [[nodiscard]] double sample_period() const { return sample_period_; }
  void reset();

 private:
  // The motion this step, from the measurement: the one place the velocity tracker sees a sample.
  PredictedMotion track(const Measurement& m);
  // The gap's field this step: the current that flows (after a coil lag) and the B it makes.
  struct Field {
    double coil_current;  // [A]
    double B;             // [T]
  };
  // Everything after B (Eq. 13, 11-12) with every effect off, and with at least one on.
  ObserverEstimate base_force(const PredictedMotion& now, double B);
  ObserverEstimate force_with_effects(const PredictedMotion& now, const Field& field);

  double sample_period_;  // [s]
  JilesAtherton magnetics_;
  YieldStress yield_stress_;
  BinghamDamper damper_;
  VelocityFilter velocity_filter_;
  EffectChain effects_;
  ObserverEstimate estimate_;
  double yield_scale_ = 1.0;
};

}  // namespace mrd::model
