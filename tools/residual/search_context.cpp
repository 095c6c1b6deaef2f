#include "tools/residual/search_context.hpp"

#include "tools/residual/model_fit.hpp"
#include "tools/residual/residual_structure.hpp"

namespace mrd::tools::search {

double Search::validation_rms(const model::DamperModel& m) const {
  std::vector<double> force;
  predict_force(m, fit_series, force);
  return residual_rms(fit_series, force).validation;
}

std::vector<double> Search::predicted(const model::DamperModel& m) const {
  std::vector<double> force;
  predict_force(m, fit_series, force);
  return force;
}

double Search::white_noise_of(const std::vector<double>& predicted) const {
  std::vector<double> residual;
  residual.reserve(fit_series.size());
  for (std::size_t i = 0; i < fit_series.size(); ++i)
    if (fit_series.role[i] != SampleRole::kExcluded) residual.push_back(fit_series.force[i] - predicted[i]);
  return tools::noise_floor(residual);  // the free function, not the member
}

}  // namespace mrd::tools::search
