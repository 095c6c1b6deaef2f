#include "model/jiles_atherton.hpp"

#include <algorithm>
#include <cmath>

#include "model/langevin.hpp"
#include "model/physical_constants.hpp"

namespace mrd::model {

namespace {

// The span of H [A/m] over which Man(H) bends. The mean field steepens it by
// 1 / (1 - alpha Ms/3a) at its steepest (He = 0), so it bends over a (1 - alpha Ms/3a); past the
// fold the span is floored at a twentieth of a.
double anhysteretic_field_scale(const JilesAthertonParams& p) {
  constexpr double kFoldedFieldScale = 0.05;
  return p.a * std::max(1.0 - p.mean_field_gain(), kFoldedFieldScale);
}

}  // namespace

JilesAtherton::JilesAtherton(const JilesAthertonParams& params, const MagneticCircuit& circuit,
                             const JilesAthertonSettings& settings)
    : p_(params),
      circuit_(circuit),
      settings_(settings),
      inv_a_(1.0 / params.a),
      alpha_over_a_(params.alpha / params.a),
      Ms_over_a_(params.Ms / params.a),
      one_minus_c_(1.0 - params.c),
      alpha_c_(params.alpha * params.c),
      k_floor_(params.k * settings.denominator_floor),
      max_field_step_(settings.max_field_step_fraction * std::min(anhysteretic_field_scale(params), params.k)) {}

double JilesAtherton::B() const { return kMu0 * (state_.H + state_.M); }  // Eq. 8

double JilesAtherton::apply_current(double current) {
  return apply_field(circuit_.field_from_current(current));  // Eq. 9
}

namespace {

struct ExactLangevin {
  LangevinValue operator()(double x) const { return langevin(x); }
};

}  // namespace

double JilesAtherton::apply_field(double H) {
  if (H != state_.H && std::isfinite(H)) {
    ExactLangevin exact;
    const bool tabulated = settings_.langevin == LangevinEvaluation::kTabulated;
    if (settings_.integrator == Integrator::kRk4) {
      tabulated ? integrate_or_recall<Integrator::kRk4>(H, langevin_cursor_)
                : integrate_or_recall<Integrator::kRk4>(H, exact);
    } else {
      tabulated ? integrate_or_recall<Integrator::kHeun>(H, langevin_cursor_)
                : integrate_or_recall<Integrator::kHeun>(H, exact);
    }
  }
  return B();
}

// Inlined into each stage: as a call it returned its result through memory and kept the
// compiler from interleaving one stage's tail with the next stage's head.
template <typename Langevin>
[[gnu::always_inline]] inline JilesAtherton::Slope JilesAtherton::slope(Langevin& langevin,
                                                                        double x, double M_irr,
                                                                        double delta) const {
  const LangevinValue L = langevin(x);
  const double Man = p_.Ms * L.value;  // Eq. 3
  const double dMan_dHe = Ms_over_a_ * L.derivative;

  bool guarded = false;
  // Eq. 10, irreversible term. When delta and (Man - M_irr) disagree the domain walls would
  // move against the field: that branch is non-physical and contributes nothing, so the
  // pinning term is max(delta (Man - M_irr), 0). delta (Man - M_irr) is formed as
  // (delta Ms) L - delta M_irr: with delta = +-1 both products are exact.
  const double drive = (delta * p_.Ms) * L.value - delta * M_irr;
  const double pinning = std::max(drive, 0.0);
  // k delta - alpha (Man - M_irr) = delta (k - alpha pinning). It reaches zero when
  // alpha |Man - M_irr| >= k (runaway); it is clamped to k * floor and the event counted.
  // k - alpha pinning is formed from L, not from pinning: the chain from L to the division is
  // then one multiply-subtract, the rest is computed while the Langevin polynomials run.
  double denominator =
      drive > 0.0 ? (p_.k + (p_.alpha * delta) * M_irr) - (p_.alpha * delta * p_.Ms) * L.value
                  : p_.k;
  if (denominator < k_floor_) {
    denominator = k_floor_;
    guarded = pinning > 0.0;
  }
  // Reversible coupling 1 - alpha c Man' folds when alpha c Ms/(3a) >= 1; same guard.
  double coupling = 1.0 - (alpha_c_ * Ms_over_a_) * L.derivative;
  if (coupling < settings_.denominator_floor) {
    coupling = settings_.denominator_floor;
    guarded = true;
  }
  // chi_irr = pinning / denominator and dM/dH = ((1-c) chi_irr + c Man') / coupling,
  // sharing one division.
  return {one_minus_c_ * pinning + p_.c * dMan_dHe * denominator, pinning * coupling,
          1.0 / (denominator * coupling), Man, guarded};
}

template <Integrator kMethod, typename Langevin>
void JilesAtherton::integrate_or_recall(double H_target, Langevin& langevin) {
  const double tolerance = settings_.jump_recall_tolerance * p_.Ms;
  if (!(tolerance > 0.0) || std::fabs(H_target - state_.H) <= kRecalledJumpSteps * max_field_step_) {
    integrate<kMethod>(H_target, langevin);
    return;
  }
  for (std::size_t j = 0; j < jumps_kept_; ++j) {
    const KeptJump& kept = kept_jumps_[j];
    if (kept.to.H == H_target && kept.from.H == state_.H && std::fabs(kept.from.M - state_.M) <= tolerance &&
        std::fabs(kept.from.M_irr - state_.M_irr) <= tolerance) {
      state_ = {H_target, state_.M + (kept.to.M - kept.from.M), state_.M_irr + (kept.to.M_irr - kept.from.M_irr)};
      ++recalled_jumps_;
      return;
    }
  }
  const MagneticState from = state_;
  integrate<kMethod>(H_target, langevin);
  kept_jumps_[next_kept_] = {from, state_};
  next_kept_ = (next_kept_ + 1) % kKeptJumps;
  jumps_kept_ = std::min(jumps_kept_ + 1, kKeptJumps);
}

template <Integrator kMethod, typename Langevin>
void JilesAtherton::integrate(double H_target, Langevin& langevin) {
  const double growth = settings_.field_step_growth;
  if (!(growth > 0.0) || std::fabs(H_target - state_.H) <= max_field_step_) {
    integrate_on_grid<kMethod>(H_target, max_field_step_, langevin);
    return;
  }
  // Steps of max(grid, g |He|): the grid where |He| is small (the knee, where M_irr relaxes
  // over k), longer where the curve is saturated. At max_substeps the rest is one step, as a
  // real-time bound (the searches' exploring cap of 64 relies on the guards there).
  const double direction = H_target > state_.H ? 1.0 : -1.0;
  for (int taken = 1; state_.H != H_target; ++taken) {
    const double He = state_.H + p_.alpha * state_.M;
    const double step = std::max(max_field_step_, growth * std::fabs(He));
    const double remaining = std::fabs(H_target - state_.H);
    const bool last = remaining <= step || taken >= settings_.max_substeps;
    const double next = last ? H_target : state_.H + direction * step;
    integrate_on_grid<kMethod>(next, last ? remaining : step, langevin);
  }
}

template <Integrator kMethod, typename Langevin>
void JilesAtherton::integrate_on_grid(double H_target, double max_step, Langevin& langevin) {
  const double span = H_target - state_.H;
  const double delta = span > 0.0 ? 1.0 : -1.0;
  // One sub-step is the real-time case (a control period moves H by far less than the grid);
  // it skips the ceil and the two divisions of the general count.
  int steps = 1;
  double h = span;
  if (std::fabs(span) > max_step) {
    steps = static_cast<int>(std::clamp(std::ceil(std::fabs(span) / max_step), 1.0,
                                        static_cast<double>(settings_.max_substeps)));
    h = span / steps;
  }

  substeps_ += static_cast<std::uint64_t>(steps);
  double M = state_.M;
  double M_irr = state_.M_irr;
  double H = state_.H;
  for (int i = 0; i < steps; ++i) {
    bool guarded = false;
    double Man_end = 0.0;
    // A stage at field H_s, `step` along slope k from the sub-step's start. Its x = He/a =
    // H_s/a + (alpha/a) M (Eq. 4): the H_s part and the part from the starting M are known
    // before the stages run, and only the increment waits for the previous stage's division.
    const double x_M = alpha_over_a_ * M;
    const auto stage = [&](double H_s, const Slope& k, double step) {
      return slope(langevin, H_s * inv_a_ + x_M + ((alpha_over_a_ * step) * k.dM_num) * k.inv,
                   M_irr + (step * k.chi_num) * k.inv, delta);
    };
    const Slope k1 = slope(langevin, H * inv_a_ + x_M, M_irr, delta);
    if constexpr (kMethod == Integrator::kRk4) {
      const double half = 0.5 * h;
      const Slope k2 = stage(H + half, k1, half);
      const Slope k3 = stage(H + half, k2, half);
      const Slope k4 = stage(H + h, k3, h);
      const double sixth = h / 6.0;
      M = (M + sixth * (k1.dM_dH() + 2.0 * k2.dM_dH() + 2.0 * k3.dM_dH())) +
          (sixth * k4.dM_num) * k4.inv;
      M_irr = (M_irr + sixth * (k1.chi_irr() + 2.0 * k2.chi_irr() + 2.0 * k3.chi_irr())) +
              (sixth * k4.chi_num) * k4.inv;
      guarded = k1.guarded || k2.guarded || k3.guarded || k4.guarded;
      Man_end = k4.Man;
    } else {
      const Slope k2 = stage(H + h, k1, h);
      const double half = 0.5 * h;
      M = (M + half * k1.dM_dH()) + (half * k2.dM_num) * k2.inv;
      M_irr = (M_irr + half * k1.chi_irr()) + (half * k2.chi_num) * k2.inv;
      guarded = k1.guarded || k2.guarded;
      Man_end = k2.Man;
    }
    guard_events_ += guarded ? 1 : 0;
    // The exact solution relaxes M_irr towards Man and never passes it. A sub-step can
    // overshoot when chi_irr is huge (near runaway, or when max_substeps stretched the step).
    // The avalanche then ends on the anhysteretic curve: M_irr = Man, so M = Man (Eq. 1-2).
    if (delta * (M_irr - Man_end) > 0.0 && delta * (M_irr - state_.M_irr) > 0.0) {
      M = M_irr = Man_end;
    }
    // |Man| < Ms (Eq. 3), so no exact solution leaves [-Ms, Ms]; a guarded step might.
    M = std::min(std::max(M, -p_.Ms), p_.Ms);
    M_irr = std::min(std::max(M_irr, -p_.Ms), p_.Ms);
    H = (i + 1 == steps) ? H_target : H + h;
    state_ = {H, M, M_irr};
    if (!std::isfinite(M) || !std::isfinite(M_irr)) {
      ++recoveries_;
      settle_on_anhysteretic();
      M = state_.M;
      M_irr = state_.M_irr;
    }
  }
}

void JilesAtherton::settle_on_anhysteretic() {
  const double M_an = anhysteretic_magnetisation(state_.H);
  state_.M = M_an;
  state_.M_irr = M_an;
}

double JilesAtherton::anhysteretic_magnetisation(double H) const {
  // g(M) = M - Ms L((H + alpha M)/a) has g(-Ms) <= 0 <= g(Ms), so a root is bracketed even
  // when alpha Ms/(3a) >= 1 makes the curve fold (then bisection picks one branch). The
  // curve is odd: solve for |H| and mirror, so M(0) = 0 exactly.
  if (H == 0.0) return 0.0;
  if (H < 0.0) return -anhysteretic_magnetisation(-H);
  double lo = -p_.Ms;
  double hi = p_.Ms;
  for (int i = 0; i < 64 && hi - lo > 1e-12 * p_.Ms; ++i) {
    const double mid = 0.5 * (lo + hi);
    const double x = (H + p_.alpha * mid) * inv_a_;
    const double L = settings_.langevin == LangevinEvaluation::kTabulated
                         ? langevin_tabulated(x).value
                         : langevin(x).value;
    const double g = mid - p_.Ms * L;
    (g > 0.0 ? hi : lo) = mid;
  }
  return 0.5 * (lo + hi);
}

}  // namespace mrd::model
