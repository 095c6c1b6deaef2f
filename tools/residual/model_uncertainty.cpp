#include "tools/residual/model_uncertainty.hpp"

#include <array>

#include "tools/report/fit_statistics.hpp"
#include "tools/residual/model_fit.hpp"

namespace mrd::tools {

namespace {

struct ModelParameter {
  const char* name;
  const char* unit;
  double& (*field)(model::DamperModel&);
};

constexpr std::array<ModelParameter, 7> kParameters = {{
    {"jiles_atherton.Ms", "A/m", [](model::DamperModel& m) -> double& { return m.jiles_atherton.Ms; }},
    {"jiles_atherton.a", "A/m", [](model::DamperModel& m) -> double& { return m.jiles_atherton.a; }},
    {"jiles_atherton.alpha", "-", [](model::DamperModel& m) -> double& { return m.jiles_atherton.alpha; }},
    {"jiles_atherton.k", "A/m", [](model::DamperModel& m) -> double& { return m.jiles_atherton.k; }},
    {"jiles_atherton.c", "-", [](model::DamperModel& m) -> double& { return m.jiles_atherton.c; }},
    {"fluid.viscosity", "Pa s", [](model::DamperModel& m) -> double& { return m.fluid.viscosity; }},
    {"geometry.pole_length", "m", [](model::DamperModel& m) -> double& { return m.geometry.pole_length; }},
}};

}  // namespace

std::vector<ParameterEstimate> model_uncertainty(const model::DamperModel& fitted, const FitSeries& series) {
  std::vector<double> x;
  model::DamperModel probe = fitted;
  for (const ModelParameter& p : kParameters) x.push_back(p.field(probe));
  std::vector<double> force;
  const auto residuals = [&](const std::vector<double>& at) {
    model::DamperModel m = fitted;
    for (std::size_t j = 0; j < kParameters.size(); ++j) kParameters[j].field(m) = at[j];
    predict_force(m, series, force);
    std::vector<double> r;
    r.reserve(series.size());
    for (std::size_t i = 0; i < series.size(); ++i)
      if (series.validation[i] != FitSeries::kExcluded) r.push_back(series.force[i] - force[i]);
    return r;
  };
  const ParameterUncertainty u = parameter_uncertainty(residuals, x);
  std::vector<ParameterEstimate> out;
  for (std::size_t j = 0; j < kParameters.size(); ++j)
    out.push_back({kParameters[j].name, kParameters[j].unit, x[j], u.standard_deviation[j]});
  return out;
}

}  // namespace mrd::tools
