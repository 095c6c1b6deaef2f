#include "model/jiles_atherton.hpp"

#include <algorithm>
#include <cmath>

#include "model/langevin.hpp"
#include "model/physical_constants.hpp"

namespace mrd::model {

JilesAtherton::JilesAtherton(const JilesAthertonParams& params, const MagneticCircuit& circuit,
                             const JilesAthertonSettings& settings)
    : p_(params),
      circuit_(circuit),
      settings_(settings),
      inv_a_(1.0 / params.a),
      Ms_over_a_(params.Ms / params.a),
      one_minus_c_(1.0 - params.c),
      alpha_c_(params.alpha * params.c),
      k_floor_(params.k * settings.denominator_floor),
      max_field_step_(settings.max_field_step_fraction * std::min(params.a, params.k)) {}

double JilesAtherton::B() const { return kMu0 * (state_.H + state_.M); }  // Eq. 8

double JilesAtherton::apply_current(double current) {
  return apply_field(circuit_.field_from_current(current));  // Eq. 9
}

double JilesAtherton::apply_field(double H) {
  if (H != state_.H && std::isfinite(H)) {
    if (settings_.integrator == Integrator::kRk4) {
      integrate<Integrator::kRk4>(H);
    } else {
      integrate<Integrator::kHeun>(H);
    }
  }
  return B();
}

// Inlined into each stage: as a call it returned its result through memory and kept the
// compiler from interleaving one stage's tail with the next stage's head.
[[gnu::always_inline]] inline JilesAtherton::Slope JilesAtherton::slope(double H, double M,
                                                                        double M_irr,
                                                                        double delta) const {
  const double He = H + p_.alpha * M;  // Eq. 4
  const LangevinValue L = langevin(He * inv_a_);
  const double Man = p_.Ms * L.value;              // Eq. 3
  const double dMan_dHe = Ms_over_a_ * L.derivative;
  const double dM = Man - M_irr;

  bool guarded = false;
  // Eq. 10, irreversible term. When delta and (Man - M_irr) disagree the domain walls would
  // move against the field: that branch is non-physical and contributes nothing.
  // k delta - alpha (Man - M_irr) = delta (k - alpha |Man - M_irr|). It reaches zero when
  // alpha |Man - M_irr| >= k (runaway); it is clamped to k * floor and the event counted.
  const double pinning = delta * dM > 0.0 ? std::fabs(dM) : 0.0;
  double denominator = p_.k - p_.alpha * pinning;
  if (denominator < k_floor_) {
    denominator = k_floor_;
    guarded = pinning > 0.0;
  }
  // Reversible coupling 1 - alpha c Man' folds when alpha c Ms/(3a) >= 1; same guard.
  double coupling = 1.0 - alpha_c_ * dMan_dHe;
  if (coupling < settings_.denominator_floor) {
    coupling = settings_.denominator_floor;
    guarded = true;
  }
  // chi_irr = pinning / denominator and dM/dH = ((1-c) chi_irr + c Man') / coupling,
  // sharing one division.
  const double inv = 1.0 / (denominator * coupling);
  const double chi_irr = pinning * coupling * inv;
  const double dM_dH = (one_minus_c_ * pinning + p_.c * dMan_dHe * denominator) * inv;
  return {dM_dH, chi_irr, Man, guarded};
}

template <Integrator kMethod>
void JilesAtherton::integrate(double H_target) {
  const double span = H_target - state_.H;
  const double delta = span > 0.0 ? 1.0 : -1.0;
  const int steps = static_cast<int>(std::clamp(std::ceil(std::fabs(span) / max_field_step_), 1.0,
                                                static_cast<double>(settings_.max_substeps)));
  const double h = span / steps;

  double M = state_.M;
  double M_irr = state_.M_irr;
  double H = state_.H;
  for (int i = 0; i < steps; ++i) {
    bool guarded = false;
    double Man_end = 0.0;
    if constexpr (kMethod == Integrator::kRk4) {
      const double half = 0.5 * h;
      const Slope k1 = slope(H, M, M_irr, delta);
      const Slope k2 = slope(H + half, M + half * k1.dM_dH, M_irr + half * k1.dM_irr_dH, delta);
      const Slope k3 = slope(H + half, M + half * k2.dM_dH, M_irr + half * k2.dM_irr_dH, delta);
      const Slope k4 = slope(H + h, M + h * k3.dM_dH, M_irr + h * k3.dM_irr_dH, delta);
      const double sixth = h / 6.0;
      M += sixth * (k1.dM_dH + 2.0 * k2.dM_dH + 2.0 * k3.dM_dH + k4.dM_dH);
      M_irr += sixth * (k1.dM_irr_dH + 2.0 * k2.dM_irr_dH + 2.0 * k3.dM_irr_dH + k4.dM_irr_dH);
      guarded = k1.guarded || k2.guarded || k3.guarded || k4.guarded;
      Man_end = k4.Man;
    } else {
      const Slope k1 = slope(H, M, M_irr, delta);
      const Slope k2 = slope(H + h, M + h * k1.dM_dH, M_irr + h * k1.dM_irr_dH, delta);
      const double half = 0.5 * h;
      M += half * (k1.dM_dH + k2.dM_dH);
      M_irr += half * (k1.dM_irr_dH + k2.dM_irr_dH);
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
    const double g = mid - p_.Ms * langevin((H + p_.alpha * mid) * inv_a_).value;
    (g > 0.0 ? hi : lo) = mid;
  }
  return 0.5 * (lo + hi);
}

}  // namespace mrd::model
