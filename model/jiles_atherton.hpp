#pragma once

#include <array>
#include <cstddef>
#include <cstdint>

#include "model/jiles_atherton_params.hpp"
#include "model/langevin.hpp"

namespace mrd::model {

enum class Integrator {
  kHeun,  // 2nd order; cheaper, kept for comparison in docs/MODEL.md
  kRk4,   // classical 4th-order Runge-Kutta; the default
};

// How the Langevin function of Eq. 3 is evaluated (model/langevin.hpp, docs/MODEL.md).
enum class LangevinEvaluation {
  // Piecewise polynomials: no exp and no division. Error below 1e-13 in L and 2e-13 in L',
  // under 1e-13 T in B. The real-time default.
  kTabulated,
  // The closed form, one exp and one division. For identification and reference runs, which
  // should not depend on a table.
  kExact,
};

struct JilesAthertonSettings {
  // Sub-steps are at most this fraction of min(a (1 - alpha Ms/3a), k) in H, so a current step
  // of any size integrates on the same grid as a slow ramp, and a strong mean field (a steeper
  // anhysteretic curve) on a finer one.
  double max_field_step_fraction = 0.25;
  // Real-time bound on work per call. A jump needing more sub-steps uses larger ones.
  int max_substeps = 4096;
  // 0: the uniform grid above. g > 0: a sub-step may also be g |He| long, so a jump far into
  // saturation, where Man bends on the scale of He itself (the mean field no longer steepens
  // it), takes a few long steps. For the fits' searches, which repeat a run thousands of
  // times; the observer keeps 0.
  double field_step_growth = 0.0;
  // 0: off. r > 0: a jump of more than kRecalledJumpSteps grid steps, between fields a kept jump
  // joined, from a state within r Ms of that jump's start, takes the kept jump's change of M and
  // M_irr instead of being integrated again (the last kKeptJumps jumps integrated are kept). A
  // current switching between a few levels repeats its jumps; J-A's minor loops ratchet (for the
  // default material M moves 0.03 A/m a cycle between 0 and 1.2 A), so an exact repeat never
  // comes and the match is within r. For the fits' searches, which replay a run thousands of
  // times; what is reported comes from the model's own integration, and the observer keeps 0.
  double jump_recall_tolerance = 0.0;
  // Denominator guard, as a fraction of k (Eq. 10) or of 1 (the reversible coupling).
  double denominator_floor = 1e-2;
  Integrator integrator = Integrator::kRk4;
  LangevinEvaluation langevin = LangevinEvaluation::kTabulated;

  bool operator==(const JilesAthertonSettings&) const = default;
};

// Where the material is on its B-H plane. H is the field the state was integrated to.
struct MagneticState {
  double H = 0.0;      // [A/m]
  double M = 0.0;      // total magnetisation [A/m], Eq. 1
  double M_irr = 0.0;  // irreversible magnetisation [A/m]
};

// Jiles-Atherton hysteresis (Eq. 1-10) driven by coil current through Eq. 8-9.
//
// Eq. 10 is integrated with H as the independent variable: within one control period the
// current is taken as linear in time, so dM/dt = (dM/dH)(dH/dt) and the time integral equals
// the integral over H. The model is rate-independent, as J-A is. The state vector is
// [M, M_irr]; expanding dMan/dt = Man'(He) (dH/dt + alpha dM/dt) in Eq. 10 gives
//   dM_irr/dH = chi_irr = (Man - M_irr) / (k delta - alpha (Man - M_irr))
//   dM/dH     = ((1 - c) chi_irr + c Man') / (1 - alpha c Man')
// Nothing here allocates, reads a clock or throws.
class JilesAtherton {
 public:
  JilesAtherton(const JilesAthertonParams& params, const MagneticCircuit& circuit,
                const JilesAthertonSettings& settings = {});

  // Drive the coil to `current` [A] and return B [T] (Eq. 8-9).
  double apply_current(double current);
  // Drive the field to `H` [A/m] and return B [T].
  double apply_field(double H);

  [[nodiscard]] double B() const;  // Eq. 8
  [[nodiscard]] double H() const { return state_.H; }
  [[nodiscard]] double M() const { return state_.M; }
  [[nodiscard]] const MagneticState& state() const { return state_; }
  void restore(const MagneticState& state) { state_ = state; }
  void demagnetise() { state_ = MagneticState{}; }

  // M on the anhysteretic curve, M = Ms L((H + alpha M)/a), by bisection. Start-up and
  // recovery paths only: about 60 Langevin evaluations.
  [[nodiscard]] double anhysteretic_magnetisation(double H) const;

  // Times a denominator of Eq. 10 was clamped (non-zero means the parameters run away
  // at this amplitude), and times a non-finite state was reset to the anhysteretic curve.
  [[nodiscard]] std::uint64_t guard_events() const { return guard_events_; }
  [[nodiscard]] std::uint64_t recoveries() const { return recoveries_; }
  // RK sub-steps taken since construction: the work the history cost.
  [[nodiscard]] std::uint64_t substeps() const { return substeps_; }
  // Jumps taken from the kept ones (jump_recall_tolerance) instead of integrated.
  [[nodiscard]] std::uint64_t recalled_jumps() const { return recalled_jumps_; }

  static constexpr std::size_t kKeptJumps = 8;
  static constexpr double kRecalledJumpSteps = 8.0;

  [[nodiscard]] const JilesAthertonParams& params() const { return p_; }
  [[nodiscard]] const MagneticCircuit& circuit() const { return circuit_; }
  [[nodiscard]] const JilesAthertonSettings& settings() const { return settings_; }

 private:
  // One stage of Eq. 10 at x = He/a (Eq. 4) and M_irr. The slopes are dM/dH = dM_num * inv and
  // chi_irr = chi_num * inv. They stay apart so that the integrator can scale the numerators
  // while the division runs: between the division and the next stage's x is one multiply-add.
  // Plain scalars, not a 2-vector: the stages are a serial chain, and scalars let the compiler
  // schedule each one freely.
  struct Slope {
    double dM_num;
    double chi_num;
    double inv;   // 1 / (denominator * coupling)
    double Man;   // anhysteretic magnetisation at this stage [A/m]
    bool guarded;
    [[nodiscard]] double dM_dH() const { return dM_num * inv; }
    [[nodiscard]] double chi_irr() const { return chi_num * inv; }
  };
  template <typename Langevin>
  [[nodiscard]] Slope slope(Langevin& langevin, double x, double M_irr, double delta) const;
  template <Integrator kMethod, typename Langevin>
  void integrate(double H_target, Langevin& langevin);
  template <Integrator kMethod, typename Langevin>
  void integrate_on_grid(double H_target, double max_step, Langevin& langevin);
  void settle_on_anhysteretic();
  template <Integrator kMethod, typename Langevin>
  void integrate_or_recall(double H_target, Langevin& langevin);

  // A jump integrated, kept for jump_recall_tolerance.
  struct KeptJump {
    MagneticState from;
    MagneticState to;
  };

  JilesAthertonParams p_;
  MagneticCircuit circuit_;
  JilesAthertonSettings settings_;
  // Cached products of the parameters, so the per-step path only multiplies.
  double inv_a_;
  double alpha_over_a_;
  double Ms_over_a_;
  double one_minus_c_;
  double alpha_c_;
  double k_floor_;
  double max_field_step_;

  MagneticState state_;
  // Where the last tabulated Langevin evaluation was: only a hint, checked on every use.
  LangevinTableCursor langevin_cursor_;
  std::uint64_t guard_events_ = 0;
  std::uint64_t substeps_ = 0;
  std::uint64_t recoveries_ = 0;
  std::uint64_t recalled_jumps_ = 0;
  std::array<KeptJump, kKeptJumps> kept_jumps_{};
  std::size_t jumps_kept_ = 0;
  std::size_t next_kept_ = 0;  // the slot the next jump integrated overwrites, oldest first
};

}  // namespace mrd::model
