#pragma once

#include <string>
#include <vector>

#include "model/damper_model.hpp"
#include "tools/residual/fit_series.hpp"

namespace mrd::tools {

// One parameter of a fitted model with its standard deviation.
struct ParameterEstimate {
  std::string name;  // config path, e.g. "jiles_atherton.Ms"
  std::string unit;
  double value = 0.0;
  double standard_deviation = 0.0;  // NaN where the run cannot determine it
};

// The standard deviations of the parameters the base fit identifies, at the final model: the
// pole length (the yield force's scale, Eq. 12), the viscosity (the viscous force), the sign
// velocity and, with `field_gain` (the current varies), the coil's turns (H = N I / Le, Eq. 9):
// sigma^2 (J^T J)^-1 over the series' kept samples (parameter_uncertainty, central differences).
// The J-A parameters are mrd-identify's (fitted to B-H loops), not this fit's.
std::vector<ParameterEstimate> model_uncertainty(const model::DamperModel& fitted, const FitSeries& series,
                                                 bool field_gain);

}  // namespace mrd::tools
