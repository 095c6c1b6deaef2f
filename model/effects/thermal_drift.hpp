#pragma once

#include <cstdint>

#include "common/validation_report.hpp"

namespace mrd::model {

enum class TemperatureLaw : std::uint8_t {
  kLinear,       // f = 1 - c (T - T_ref)
  kExponential,  // f = exp(-c (T - T_ref)), Andrade-like, the usual law for a carrier oil's viscosity
};

// MR fluid heats as the damper dissipates power, and both its viscosity and (less) its yield
// stress fall with temperature (e.g. Sahin, Cesmeci and Wereley; Batterbee and Sims 2009).
// A lumped thermal state, one heat capacity C for fluid and body, cooled towards ambient:
//   C dT/dt = P - C (T - T_amb) / tau_th,   P = max(F_fluid v, 0),
// scales the Bingham parts:
//   c0(T) = c0 f_visc(T),   tau_y(T) = tau_y f_yield(T),
// each factor linear or exponential in T - T_ref, T_ref the temperature at which the base model
// was identified, and never below `min_factor`. When a run logs the fluid temperature the
// measured value replaces the lumped state (set_measured_temperature). Temperatures in degC.
struct ThermalDriftParams {
  bool enabled = false;
  double initial_temperature = 20.0;     // [degC]
  double ambient_temperature = 20.0;     // [degC]
  double reference_temperature = 20.0;   // [degC], both factors are 1 here
  double heat_capacity = 2e4;            // C [J/K]
  double cooling_time_constant = 600.0;  // tau_th [s]
  TemperatureLaw viscosity_law = TemperatureLaw::kExponential;
  double viscosity_coefficient = 0.02;   // [1/K]
  TemperatureLaw yield_law = TemperatureLaw::kLinear;
  double yield_coefficient = 0.004;      // [1/K]
  double min_factor = 0.05;              // [-], floor of both factors
};

ValidationReport validate(const ThermalDriftParams& params);

// Exact discretisation for a power held over one period T:
//   T_end = T_inf + (T - T_inf) exp(-T/tau_th),   T_inf = T_amb + P tau_th / C,
// stable at any rate. No heap, no exceptions; a non-finite power is ignored.
class ThermalDrift {
 public:
  ThermalDrift(const ThermalDriftParams& params, double sample_period);

  // One period of dissipated power [W]: advances the lumped temperature (ignored while a
  // measured temperature is set) and updates the factors.
  void heat(double power);
  // A measured fluid temperature [degC] replaces the lumped state; NaN returns to the model.
  void set_measured_temperature(double celsius);
  [[nodiscard]] double temperature() const;
  [[nodiscard]] double viscosity_factor() const { return viscosity_factor_; }
  [[nodiscard]] double yield_factor() const { return yield_factor_; }
  void reset();

 private:
  void update_factors();

  ThermalDriftParams p_;
  double decay_;          // exp(-T / tau_th)
  double rise_per_watt_;  // tau_th / C [K/W]
  double temperature_;
  double measured_;       // NaN when none
  double viscosity_factor_ = 1.0;
  double yield_factor_ = 1.0;
};

}  // namespace mrd::model
