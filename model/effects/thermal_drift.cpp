#include "model/effects/thermal_drift.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <cstdio>

namespace mrd::model {

namespace {
// One property's law of the temperature rise, named so that its numbers cannot swap.
struct DriftLaw {
  TemperatureLaw law;
  double coefficient;  // [1/degC]
  double floor;        // the least factor [-]
};
double factor(const DriftLaw& d, double rise) {
  const double f = d.law == TemperatureLaw::kLinear ? 1.0 - d.coefficient * rise : std::exp(-d.coefficient * rise);
  return std::max(f, d.floor);
}
}  // namespace

ValidationReport validate(const ThermalDriftParams& p) {
  ValidationReport report;
  report.require_in_range("initial_temperature", p.initial_temperature, -80.0, 300.0, false);
  report.require_in_range("ambient_temperature", p.ambient_temperature, -80.0, 300.0, false);
  report.require_in_range("reference_temperature", p.reference_temperature, -80.0, 300.0, false);
  report.require_positive("heat_capacity", p.heat_capacity);
  report.require_positive("cooling_time_constant", p.cooling_time_constant);
  // Negative coefficients would make the fluid stiffen as it heats: outside this effect.
  report.require_in_range("viscosity_coefficient", p.viscosity_coefficient, 0.0, 1.0, false);
  report.require_in_range("yield_coefficient", p.yield_coefficient, 0.0, 1.0, false);
  report.require_in_range("min_factor", p.min_factor, 0.0, 1.0, false);
  return report;
}

ThermalDrift::ThermalDrift(const ThermalDriftParams& params, double sample_period)
    : p_(params),
      decay_(std::exp(-sample_period / params.cooling_time_constant)),
      rise_per_watt_(params.cooling_time_constant / params.heat_capacity),
      temperature_(params.initial_temperature),
      measured_(std::numeric_limits<double>::quiet_NaN()) {
  update_factors();
}

void ThermalDrift::heat(double power) {
  if (!std::isfinite(power)) return;
  const double settled = p_.ambient_temperature + std::max(power, 0.0) * rise_per_watt_;
  temperature_ = settled + (temperature_ - settled) * decay_;
  if (std::isnan(measured_)) update_factors();
}

void ThermalDrift::set_measured_temperature(double celsius) {
  if (std::isinf(celsius)) return;  // a broken sensor value: keep what we had
  measured_ = celsius;
  update_factors();
}

double ThermalDrift::temperature() const { return std::isnan(measured_) ? temperature_ : measured_; }

void ThermalDrift::reset() {
  temperature_ = p_.initial_temperature;
  measured_ = std::numeric_limits<double>::quiet_NaN();
  update_factors();
}

void ThermalDrift::update_factors() {
  const double rise = temperature() - p_.reference_temperature;
  viscosity_factor_ =
      factor({.law = p_.viscosity_law, .coefficient = p_.viscosity_coefficient, .floor = p_.min_factor}, rise);
  yield_factor_ = factor({.law = p_.yield_law, .coefficient = p_.yield_coefficient, .floor = p_.min_factor}, rise);
}

void ThermalDriftEffect::apply(Params& p, std::span<const double> x, const RunScales& s) {
  p = ThermalDriftParams{};
  p.enabled = true;
  p.viscosity_law = TemperatureLaw::kExponential;
  p.yield_law = TemperatureLaw::kLinear;
  if (s.measured_temperature) {
    p.viscosity_coefficient = x[0];
    p.yield_coefficient = x[1];
  } else {
    p.heat_capacity = std::max(s.dissipated_energy, 1e-9) / kNominalRise;
    p.viscosity_coefficient = x[0] / kNominalRise;
    p.yield_coefficient = x[1] / kNominalRise;
  }
}

void ThermalDriftEffect::coordinates(const Params& p, const RunScales& s, std::span<double> x) {
  const double scale = s.measured_temperature ? 1.0 : kNominalRise;
  x[0] = p.viscosity_coefficient * scale;
  x[1] = p.yield_coefficient * scale;
}

std::optional<std::string> ThermalDriftEffect::implausible(const Params& p, const RunScales& s) {
  std::array<double, 2> x{};
  coordinates(p, s, x);
  if (x[0] + x[1] < 0.01) return "drops below 1 %";
  return std::nullopt;
}

std::string ThermalDriftEffect::size_summary(const Params&) {
  char text[64];
  std::snprintf(text, sizeof text, "the run heats the fluid by %.3g K", kNominalRise);
  return text;
}

}  // namespace mrd::model
