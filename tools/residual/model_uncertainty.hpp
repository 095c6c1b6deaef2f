#pragma once

#include <cmath>
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
  bool shape = false;  // a shape coordinate about 0 (its sd is judged against 1, not the value)
  std::vector<double> correlation;  // with each estimate of the list, in order; NaN: not determined
};

// Whether the run determines the parameter: a finite standard deviation no larger than the
// value (a shape's: than 1, its range's scale; a value on its bound of 0, such as no seal
// friction or no yield ceiling: any finite one).
[[nodiscard]] inline bool determined(const ParameterEstimate& p) {
  if (!std::isfinite(p.standard_deviation)) return false;
  if (p.shape) return p.standard_deviation <= 1.0;
  return p.value == 0.0 || p.standard_deviation <= std::fabs(p.value);
}

// The standard deviations of the parameters the base fit identifies, at the final model
// (the list in model_uncertainty.cpp; `freed` says which magnetic ones the run determined):
// sigma^2 (J^T J)^-1 over the series' kept samples (parameter_uncertainty, central differences).
std::vector<ParameterEstimate> model_uncertainty(const model::DamperModel& fitted, const FitSeries& series,
                                                 Magnetics freed);

}  // namespace mrd::tools
