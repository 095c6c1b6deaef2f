#pragma once

#include <string>
#include <vector>

#include "model/damper_model.hpp"
#include "tools/residual/candidate_effects.hpp"
#include "tools/residual/fit_series.hpp"

namespace mrd::tools {

// One parameter of a fitted model with its standard deviation.
struct ParameterEstimate {
  std::string name;  // config path, e.g. "jiles_atherton.Ms"
  std::string unit;
  double value = 0.0;
  double standard_deviation = 0.0;  // NaN where the run cannot determine it
};

// The standard deviations of the parameters the base fit identifies, at the final model
// (the list in model_uncertainty.cpp; `freed` says which magnetic ones the run determined):
// sigma^2 (J^T J)^-1 over the series' kept samples (parameter_uncertainty, central differences).
std::vector<ParameterEstimate> model_uncertainty(const model::DamperModel& fitted, const FitSeries& series,
                                                 Magnetics freed);

}  // namespace mrd::tools
