#include "tools/table4/table4_run.hpp"

#include <algorithm>
#include <cmath>

#include "model/bingham_damper.hpp"
#include "model/mr_fluid.hpp"
#include "sim/damper_plant.hpp"

namespace mrd::tools {

namespace {
class ErrorAccumulator {
 public:
  void add(double error) {
    sum_sq_ += error * error;
    max_ = std::max(max_, std::fabs(error));
    ++n_;
  }
  [[nodiscard]] ErrorFigures figures() const {
    return {n_ ? std::sqrt(sum_sq_ / static_cast<double>(n_)) : 0.0, max_};
  }

 private:
  double sum_sq_ = 0.0;
  double max_ = 0.0;
  long n_ = 0;
};
}  // namespace

Table4RunResult run_table4(const Table4RunOptions& options) {
  const double dt = options.controller.observer.sample_period;
  const auto samples = static_cast<long>(std::llround(options.cycles / options.profile.frequency / dt));
  const auto first_cycle = static_cast<long>(std::llround(1.0 / options.profile.frequency / dt));

  control::ControlLaw law(options.controller);
  sim::DamperPlant plant(options.plant, options.lvdt_noise_rms, options.seed);
  const model::YieldStress yield_stress(options.plant.fluid);
  const model::BinghamDamper bingham(options.plant.geometry, options.plant.fluid.viscosity, options.plant.fluid.flow_index);

  Table4RunResult result;
  result.trace.reserve(static_cast<std::size_t>(samples));
  ErrorAccumulator B_error, force_error, observer_error;
  double coil_current = 0.0;  // the command of the previous period flows during this one
  double intended_B = 0.0;    // what that command was meant to reach
  for (long i = 0; i < samples; ++i) {
    const double t = static_cast<double>(i) * dt;
    const double x = options.profile.displacement(t);
    const double v = options.profile.velocity(t);
    const sim::PlantReading reading = plant.step({.displacement = x, .velocity = v, .coil_current = coil_current});
    const auto& seen = law.observe({.displacement = reading.lvdt_displacement, .coil_current = coil_current});
    const control::ControlLaw::Command command = law.command();

    Table4Sample s;
    s.time = t;
    s.displacement = x;
    s.scheduled_current = seen.scheduled_current;
    s.command_current = coil_current;
    s.target_B = intended_B;
    s.B = reading.B;
    s.force = reading.force;
    s.intended_force = bingham.force({.velocity = v, .yield_stress = yield_stress(intended_B)});
    s.observer_force = seen.estimate.force;
    if (i >= first_cycle) {
      B_error.add(s.B - s.target_B);
      force_error.add(s.force - s.intended_force);
      observer_error.add(s.observer_force - s.force);
      result.peak_force = std::max(result.peak_force, std::fabs(s.force));
    }
    result.trace.push_back(s);
    coil_current = command.current;
    intended_B = command.target_B;
  }
  result.B_tracking = B_error.figures();
  result.force_vs_intended = force_error.figures();
  result.observer_force = observer_error.figures();
  return result;
}

}  // namespace mrd::tools
