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

// What the base fit identifies (base_identification.cpp, describe_base): the force scale as the pole
// length, the viscous coefficient as the viscosity, the sign and flow shapes; then, where the
// current varies, the seal friction (at a constant current it and the force scale are one
// direction), the field gain as the coil's turns and the yield law; last, where the material is free, the J-A shape (a and Ms are tied to the field gain
// and the force scale, so they have none of their own).
constexpr std::size_t kAlways = 5;
constexpr std::size_t kWithGain = 10;
constexpr std::array<ModelParameter, 13> kParameters = {{
    {"geometry.pole_length", "m", [](model::DamperModel& m) -> double& { return m.geometry.pole_length; }},
    {"fluid.viscosity", "Pa s", [](model::DamperModel& m) -> double& { return m.fluid.viscosity; }},
    {"geometry.sign_velocity_scale", "m/s", [](model::DamperModel& m) -> double& { return m.geometry.sign_velocity_scale; }},
    {"geometry.sign_shape", "-", [](model::DamperModel& m) -> double& { return m.geometry.sign_shape; }},
    {"fluid.flow_index", "-", [](model::DamperModel& m) -> double& { return m.fluid.flow_index; }},
    {"geometry.seal_friction", "N", [](model::DamperModel& m) -> double& { return m.geometry.seal_friction; }},
    {"circuit.turns", "-", [](model::DamperModel& m) -> double& { return m.circuit.turns; }},
    {"fluid.field_exponent", "-", [](model::DamperModel& m) -> double& { return m.fluid.field_exponent; }},
    {"fluid.saturation_induction", "T", [](model::DamperModel& m) -> double& { return m.fluid.saturation_induction; }},
    {"fluid.saturation_shape", "-", [](model::DamperModel& m) -> double& { return m.fluid.saturation_shape; }},
    {"jiles_atherton.k", "A/m", [](model::DamperModel& m) -> double& { return m.jiles_atherton.k; }},
    {"jiles_atherton.c", "-", [](model::DamperModel& m) -> double& { return m.jiles_atherton.c; }},
    {"jiles_atherton.alpha", "-", [](model::DamperModel& m) -> double& { return m.jiles_atherton.alpha; }},
}};

}  // namespace

std::vector<ParameterEstimate> model_uncertainty(const model::DamperModel& fitted, const FitSeries& series,
                                                 Magnetics freed) {
  const std::size_t count = freed == Magnetics::kMaterial ? kParameters.size()
                            : freed == Magnetics::kGain   ? kWithGain
                                                          : kAlways;
  std::vector<double> x;
  model::DamperModel probe = fitted;
  for (std::size_t j = 0; j < count; ++j) x.push_back(kParameters[j].field(probe));
  std::vector<double> force;
  // The columns of what acts after B share one J-A pass.
  const InductionTrace trace(fitted, series);
  const auto residuals = [&](const std::vector<double>& at) {
    model::DamperModel m = fitted;
    for (std::size_t j = 0; j < count; ++j) kParameters[j].field(m) = at[j];
    predict_force(m, series, force, &trace);
    std::vector<double> r;
    r.reserve(series.size());
    for (std::size_t i = 0; i < series.size(); ++i)
      if (series.role[i] != SampleRole::kExcluded) r.push_back(series.force[i] - force[i]);
    return r;
  };
  const ParameterUncertainty u = parameter_uncertainty(residuals, x);
  std::vector<ParameterEstimate> out;
  for (std::size_t j = 0; j < count; ++j) {
    const std::string_view name = kParameters[j].name;
    out.push_back({kParameters[j].name, kParameters[j].unit, x[j], u.standard_deviation[j], name.ends_with("_shape"),
                   u.correlation[j]});
  }
  return out;
}

}  // namespace mrd::tools
