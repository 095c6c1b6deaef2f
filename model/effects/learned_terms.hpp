#pragma once

#include <array>
#include <cmath>
#include <optional>
#include <span>
#include <string>
#include <string_view>

#include "common/validation_report.hpp"
#include "model/effects/effect_traits.hpp"

namespace mrd::model {

// What a state-dependent force term reads, all at the observer's present step.
struct ForceState {
  double displacement = 0.0;  // [m]
  double velocity = 0.0;      // [m/s]
  double acceleration = 0.0;  // [m/s^2]
  double coil_current = 0.0;  // [A], the current that flows
  double B = 0.0;             // [T]
};

// Force terms that mrd-residual discovered in a run's residual by sparse regression over a
// documented library (docs/CLOSING-THE-LOOP.md, "Discovery"), when no named effect explained it:
//   F_learned = sum_k c_k phi_k(x, v, a, I, B).
// Each coefficient carries its SI unit; zero switches its term off. Interference (mains lines)
// describes the measurement, not the damper, and never becomes a term here.
enum class LearnedTerm : std::uint8_t {
  kDisplacement,         // x                [N/m]
  kDisplacementCubed,    // x^3              [N/m^3]
  kVelocity,             // v                [N s/m]
  kVelocityAbsVelocity,  // v |v|            [N s^2/m^2]
  kSignVelocity,         // sign(v)          [N], a Coulomb friction
  kAcceleration,         // a                [kg], a moving mass
  kCurrentVelocity,      // I v              [N s/(m A)]
  kFieldVelocity,        // B v              [N s/(m T)], a viscosity that grows with the field
  kCount,
};
inline constexpr std::size_t kLearnedTermCount = static_cast<std::size_t>(LearnedTerm::kCount);

struct LearnedTermInfo {
  std::string_view name;  // the TOML key and the report's name
  std::string_view unit;  // of the coefficient, SI
  // The sign physics allows the coefficient: +1 only >= 0 (a mass, a friction, a dissipation),
  // 0 either sign.
  int sign;
};
inline constexpr std::array<LearnedTermInfo, kLearnedTermCount> kLearnedTerms = {{
    {"displacement", "N/m", 0},
    {"displacement_cubed", "N/m^3", 0},
    {"velocity", "N s/m", 0},
    {"velocity_abs_velocity", "N s^2/m^2", 1},
    {"sign_velocity", "N", 1},
    {"acceleration", "kg", 1},
    {"current_velocity", "N s/(m A)", 1},
    {"field_velocity", "N s/(m T)", 1},
}};

// The velocity below which sign(v) is smoothed (tanh), so a friction term does not chatter on
// a noisy velocity near rest.
inline constexpr double kLearnedSignVelocity = 1e-3;  // [m/s]

[[nodiscard]] inline double learned_term_value(LearnedTerm term, const ForceState& s) {
  switch (term) {
    case LearnedTerm::kDisplacement: return s.displacement;
    case LearnedTerm::kDisplacementCubed: return s.displacement * s.displacement * s.displacement;
    case LearnedTerm::kVelocity: return s.velocity;
    case LearnedTerm::kVelocityAbsVelocity: return s.velocity * std::fabs(s.velocity);
    case LearnedTerm::kSignVelocity: return std::tanh(s.velocity / kLearnedSignVelocity);
    case LearnedTerm::kAcceleration: return s.acceleration;
    case LearnedTerm::kCurrentVelocity: return s.coil_current * s.velocity;
    case LearnedTerm::kFieldVelocity: return s.B * s.velocity;
    case LearnedTerm::kCount: break;
  }
  return 0.0;
}

struct LearnedTermsParams {
  bool enabled = false;
  std::array<double, kLearnedTermCount> coefficients{};  // SI, in LearnedTerm order

  [[nodiscard]] double& operator[](LearnedTerm t) { return coefficients[static_cast<std::size_t>(t)]; }
  [[nodiscard]] double operator[](LearnedTerm t) const { return coefficients[static_cast<std::size_t>(t)]; }
  bool operator==(const LearnedTermsParams&) const = default;
};

ValidationReport validate(const LearnedTermsParams& params);

// The acceleration is the backward difference of the velocity the observer steps with, its own
// rather than the tracker's: the tracker reconstructs it from the displacement with a causal
// filter whose lag would misplace a mass term by tens of per cent on a 5 Hz motion.
class LearnedTerms {
 public:
  LearnedTerms(const LearnedTermsParams& params, double sample_period)
      : coefficients_(params.coefficients), inverse_period_(1.0 / sample_period) {}
  double force(const ForceState& s) {
    ForceState now = s;
    now.acceleration = has_previous_ ? (s.velocity - previous_velocity_) * inverse_period_ : 0.0;
    previous_velocity_ = s.velocity;
    has_previous_ = true;
    double f = 0.0;
    for (std::size_t k = 0; k < kLearnedTermCount; ++k) {
      if (coefficients_[k] != 0.0) f += coefficients_[k] * learned_term_value(static_cast<LearnedTerm>(k), now);
    }
    return f;
  }
  void reset() { has_previous_ = false; }
  // The next steps' length [s], for samples taken unevenly (EffectChain::set_step).
  void set_step(double dt) { inverse_period_ = 1.0 / dt; }

 private:
  std::array<double, kLearnedTermCount> coefficients_;
  double inverse_period_;
  double previous_velocity_ = 0.0;
  bool has_previous_ = false;
};

// The descriptor (effect_traits.hpp). Not a named candidate: its coefficients come from the
// discovery step's regression, not from a search, and the simulator does not size it.
struct LearnedTermsEffect : EffectTraitsBase<LearnedTermsParams> {
  using Element = LearnedTerms;
  static constexpr std::string_view kName = "learned_terms";
  static constexpr bool kNamedCandidate = false;
  // Hook (effect_chain.hpp): a force added from the whole state.
  static double state_force(Element& terms, const ForceState& s) { return terms.force(s); }

  template <typename Visitor>
  static void fields(Params& p, Visitor&& v) {
    v("enabled", p.enabled);
    for (std::size_t k = 0; k < kLearnedTermCount; ++k) v(kLearnedTerms[k].name, p.coefficients[k]);
  }
  static void scale_force(Params& p, double a) {
    for (double& c : p.coefficients) c *= a;
  }
  template <typename Visitor>
  static void report(const Params& p, Visitor&& v) {
    for (std::size_t k = 0; k < kLearnedTermCount; ++k)
      if (p.coefficients[k] != 0.0) v(kLearnedTerms[k].name, p.coefficients[k]);
  }
  static void resize(Params& p, double size, double /*dissipated_energy*/) {
    p.enabled = true;
    for (double& c : p.coefficients) c *= size;
  }
  static std::string size_summary(const Params& p);
};

}  // namespace mrd::model
