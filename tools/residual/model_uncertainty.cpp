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

// What the base fit identifies (residual_search.cpp, describe_base): the force scale as the pole
// length, the viscous coefficient as the viscosity, the sign velocity and, last, the field gain
// as the coil's turns.
constexpr std::array<ModelParameter, 4> kParameters = {{
    {"geometry.pole_length", "m", [](model::DamperModel& m) -> double& { return m.geometry.pole_length; }},
    {"fluid.viscosity", "Pa s", [](model::DamperModel& m) -> double& { return m.fluid.viscosity; }},
    {"geometry.sign_velocity_scale", "m/s", [](model::DamperModel& m) -> double& { return m.geometry.sign_velocity_scale; }},
    {"circuit.turns", "-", [](model::DamperModel& m) -> double& { return m.circuit.turns; }},
}};

}  // namespace

std::vector<ParameterEstimate> model_uncertainty(const model::DamperModel& fitted, const FitSeries& series,
                                                 bool field_gain) {
  const std::size_t count = field_gain ? kParameters.size() : kParameters.size() - 1;
  std::vector<double> x;
  model::DamperModel probe = fitted;
  for (std::size_t j = 0; j < count; ++j) x.push_back(kParameters[j].field(probe));
  std::vector<double> force;
  const auto residuals = [&](const std::vector<double>& at) {
    model::DamperModel m = fitted;
    for (std::size_t j = 0; j < count; ++j) kParameters[j].field(m) = at[j];
    predict_force(m, series, force);
    std::vector<double> r;
    r.reserve(series.size());
    for (std::size_t i = 0; i < series.size(); ++i)
      if (series.validation[i] != FitSeries::kExcluded) r.push_back(series.force[i] - force[i]);
    return r;
  };
  const ParameterUncertainty u = parameter_uncertainty(residuals, x);
  std::vector<ParameterEstimate> out;
  for (std::size_t j = 0; j < count; ++j)
    out.push_back({kParameters[j].name, kParameters[j].unit, x[j], u.standard_deviation[j]});
  return out;
}

}  // namespace mrd::tools
