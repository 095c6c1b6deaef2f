#pragma once

#include <cmath>
#include <string_view>
#include <utility>
#include <array>
#include <algorithm>
#include <optional>
#include <span>
#include <string>
#include <cstdint>

#include "common/validation_report.hpp"
#include "model/effects/effect_traits.hpp"

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

  bool operator==(const ThermalDriftParams&) const = default;
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
  // The next steps' length [s], for samples taken unevenly (EffectChain::set_step).
  void set_step(double dt) { decay_ = std::exp(-dt / p_.cooling_time_constant); }
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

// The descriptor (effect_traits.hpp). A run rarely logs the fluid temperature, so the search
// asks how much viscosity and yield stress fell over a nominal rise of kNominalRise, the heat
// capacity sized so that the run's dissipated energy gives that rise; with a logged
// temperature it searches the two coefficients themselves.
struct ThermalDriftEffect : EffectTraitsBase<ThermalDriftParams> {
  using Element = ThermalDrift;
  static constexpr std::string_view kName = "thermal_drift";
  static constexpr std::string_view kSeparatedBy =
      "a long run with a rest, and the fluid temperature logged (drift follows the dissipated energy)";
  static constexpr double kNominalRise = 20.0;  // [K]
  static constexpr bool kSizedByDissipatedEnergy = true;
  // Hooks (effect_chain.hpp): the factors on tau_y and c0, and the heat of the fluid force.
  static double yield_factor(const Element& e) { return e.yield_factor(); }
  static double viscosity_factor(const Element& e) { return e.viscosity_factor(); }
  static void dissipate(Element& e, double power) { e.heat(power); }
  static void set_measured_temperature(Element& e, double celsius) { e.set_measured_temperature(celsius); }
  static double temperature(const Element& e, const Params& p, bool enabled) {
    return enabled ? e.temperature() : p.ambient_temperature;
  }

  template <typename Visitor>
  static void fields(Params& p, Visitor&& v) {
    v("enabled", p.enabled);
    v("initial_temperature", p.initial_temperature);
    v("ambient_temperature", p.ambient_temperature);
    v("reference_temperature", p.reference_temperature);
    v("heat_capacity", p.heat_capacity);
    v("cooling_time_constant", p.cooling_time_constant);
    v("viscosity_law", p.viscosity_law);
    v("viscosity_coefficient", p.viscosity_coefficient);
    v("yield_law", p.yield_law);
    v("yield_coefficient", p.yield_coefficient);
    v("min_factor", p.min_factor);
  }

  static constexpr std::array kSearch = {
      SearchCoordinate{"viscous drop over the nominal rise (or coefficient [1/K] when measured)",
                       [](const RunScales&) { return 0.0; },
                       [](const RunScales& s) { return s.measured_temperature ? 0.1 : 2.0; }},
      SearchCoordinate{"yield drop over the nominal rise (or coefficient [1/K] when measured)",
                       [](const RunScales&) { return 0.0; },
                       [](const RunScales& s) { return s.measured_temperature ? 0.05 : 0.9; }}};
  static void apply(Params& p, std::span<const double> x, const RunScales& s);
  static void coordinates(const Params& p, const RunScales& s, std::span<double> x);
  static std::optional<std::string> implausible(const Params& p, const RunScales& s);
  template <typename Visitor>
  static void report(const Params& p, Visitor&& v) {
    v("heat_capacity_J_K", p.heat_capacity);
    v("viscosity_coefficient_1_K", p.viscosity_coefficient);
    v("yield_coefficient_1_K", p.yield_coefficient);
  }
  // The size scales the rise: C such that the run's dissipated energy heats the fluid by
  // size x kNominalRise (cooling aside).
  static void resize(Params& p, double size, double dissipated_energy) {
    p.enabled = true;
    p.heat_capacity = std::max(dissipated_energy, 1.0) / (size * kNominalRise);
  }
  static std::string size_summary(const Params& p);
};

// The names of the temperature laws in configs.
[[nodiscard]] constexpr std::array<std::pair<std::string_view, TemperatureLaw>, 2> enum_choices(TemperatureLaw) {
  return {{{"linear", TemperatureLaw::kLinear}, {"exponential", TemperatureLaw::kExponential}}};
}
}  // namespace mrd::model
