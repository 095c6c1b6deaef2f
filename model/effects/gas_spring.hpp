#pragma once

#include <optional>
#include <span>
#include <string>
#include "common/validation_report.hpp"
#include "model/effects/effect_traits.hpp"

namespace mrd::model {

// The gas accumulator of a single-tube damper: its pressure on the rod adds a force that does not
// depend on velocity or field,
//   F_gas = F0 + k x,
// F0 the preload at x = 0 and k the gas stiffness (rod volume entering the accumulator). Spencer
// et al. (1997) model it the same way, k1 (x - x0), on Dyke's damper: k1 = 500 N/m, k1 x0 = 71.5 N.
// F0 carries the sign convention of the force measurement and may be negative; in the project's
// convention (x and F positive in extension) the compressed gas pushes harder, k >= 0, which
// the fits hold to.
struct GasSpringParams {
  bool enabled = false;
  double preload = 0.0;    // F0 [N]
  double stiffness = 0.0;  // k [N/m]

  bool operator==(const GasSpringParams&) const = default;
};

ValidationReport validate(const GasSpringParams& params);

class GasSpring {
 public:
  explicit GasSpring(const GasSpringParams& params)
      : preload_(params.preload), stiffness_(params.stiffness) {}
  [[nodiscard]] double force(double displacement) const { return preload_ + stiffness_ * displacement; }

 private:
  double preload_;
  double stiffness_;
};

// The descriptor (effect_traits.hpp): F0 and k enter the force linearly, so the fit solves them
// with the linear terms instead of searching.
struct GasSpringEffect : EffectTraitsBase<GasSpringParams> {
  using Element = GasSpring;
  static constexpr std::string_view kName = "gas_spring";
  static constexpr std::string_view kSeparatedBy =
      "a slow stroke at zero current (the spring is the only force that does not reverse with the velocity)";
  static constexpr std::array<std::string_view, 1> kTermForms = {"displacement"};  // k x
  // Hook (effect_chain.hpp): a force added to the fluid's.
  static double added_force(const Element& spring, double displacement) { return spring.force(displacement); }

  template <typename Visitor>
  static void fields(Params& p, Visitor&& v) {
    v("enabled", p.enabled);
    v("preload", p.preload);
    v("stiffness", p.stiffness);
  }

  static constexpr std::array kLinear = {LinearColumn::kConstant, LinearColumn::kDisplacement};
  // A gas spring stiffens as it compresses; the preload carries the force's sign convention.
  static constexpr std::array kLinearNonNegative = {false, true};
  static void linear_values(const Params& p, std::span<double> v) {
    v[0] = p.preload;
    v[1] = p.stiffness;
  }
  static void add_linear(Params& p, std::span<const double> c) {
    p.enabled = true;
    p.preload += c[0];
    p.stiffness += c[1];
  }
  static void scale_force(Params& p, double a) {
    if (!p.enabled) return;
    p.preload *= a;
    p.stiffness *= a;
  }
  static std::optional<std::string> implausible(const Params& p, const RunScales&);
  template <typename Visitor>
  static void report(const Params& p, Visitor&& v) {
    v("preload_N", p.preload);
    v("stiffness_N_m", p.stiffness);
  }
  static Params nominal(DamperClassId damper) {
    // The 1 kN class's is Spencer's k1 = 500 N/m and k1 x0 = 71.5 N.
    if (damper == DamperClassId::k50kN) return {.enabled = false, .preload = 1500.0, .stiffness = 30e3};
    return {.enabled = false, .preload = 70.0, .stiffness = 500.0};
  }
  static void resize(Params& p, double size, double /*dissipated_energy*/) {
    p.enabled = true;
    p.preload *= size;
    p.stiffness *= size;
  }
  static std::string size_summary(const Params& p);
};
}  // namespace mrd::model
