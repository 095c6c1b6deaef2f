#include "tools/residual/spencer_reference.hpp"

#include <vector>

#include "model/spencer_bouc_wen.hpp"
#include "record/csv.hpp"

namespace mrd::tools {

std::vector<double> spencer_dyke_prediction(const record::RecordedRun& run, const FitSeries& series) {
  if (run.coil_signal != record::CoilSignal::kCommandVoltage)
    throw record::InputError(run.name + ": Spencer's model takes the driver's command voltage; the run logged a current");
  model::SpencerBoucWen spencer(model::SpencerBoucWenParams::dyke_prototype(), 1.0 / run.sample_rate);
  spencer.reset(run.displacement.front());
  std::vector<double> force(run.size());
  for (std::size_t i = 0; i < run.size(); ++i)
    force[i] = spencer.step({.displacement = run.displacement[i], .velocity = series.velocity[i], .command_voltage = run.coil[i]});
  return force;
}

}  // namespace mrd::tools
