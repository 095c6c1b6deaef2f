#include "tools/residual/search_context.hpp"

#include "tools/residual/model_fit.hpp"

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

}  // namespace mrd::tools::search
