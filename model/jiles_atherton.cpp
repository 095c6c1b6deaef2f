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

JilesAtherton::Slope JilesAtherton::slope(double H, const Vec2& m, double delta) const {
  const double He = H + p_.alpha * m[0];  // Eq. 4
  const LangevinValue L = langevin(He * inv_a_);
  const double Man = p_.Ms * L.value;              // Eq. 3
  const double dMan_dHe = Ms_over_a_ * L.derivative;
  const double dM = Man - m[1];

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
  return {Vec2(dM_dH, chi_irr), Man, guarded};
}

template <Integrator kMethod>
void JilesAtherton::integrate(double H_target) {
  const double span = H_target - state_.H;
  const double delta = span > 0.0 ? 1.0 : -1.0;
  const int steps = static_cast<int>(std::clamp(std::ceil(std::fabs(span) / max_field_step_), 1.0,
                                                static_cast<double>(settings_.max_substeps)));
  const double h = span / steps;

  Vec2 m(state_.M, state_.M_irr);
  double H = state_.H;
  for (int i = 0; i < steps; ++i) {
    bool guarded = false;
    double Man_end = 0.0;
    if constexpr (kMethod == Integrator::kRk4) {
      const Slope k1 = slope(H, m, delta);
      const Slope k2 = slope(H + 0.5 * h, m + 0.5 * h * k1.dm_dH, delta);
      const Slope k3 = slope(H + 0.5 * h, m + 0.5 * h * k2.dm_dH, delta);
      const Slope k4 = slope(H + h, m + h * k3.dm_dH, delta);
      m += (h / 6.0) * (k1.dm_dH + 2.0 * k2.dm_dH + 2.0 * k3.dm_dH + k4.dm_dH);
      guarded = k1.guarded || k2.guarded || k3.guarded || k4.guarded;
      Man_end = k4.Man;
    } else {
      const Slope k1 = slope(H, m, delta);
      const Slope k2 = slope(H + h, m + h * k1.dm_dH, delta);
      m += (0.5 * h) * (k1.dm_dH + k2.dm_dH);
      guarded = k1.guarded || k2.guarded;
      Man_end = k2.Man;
    }
    guard_events_ += guarded ? 1 : 0;
    // The exact solution relaxes M_irr towards Man and never passes it. A sub-step can
    // overshoot when chi_irr is huge (near runaway, or when max_substeps stretched the step).
    // The avalanche then ends on the anhysteretic curve: M_irr = Man, so M = Man (Eq. 1-2).
    if (delta * (m[1] - Man_end) > 0.0 && delta * (m[1] - state_.M_irr) > 0.0) {
      m = Vec2(Man_end, Man_end);
    }
    // |Man| < Ms (Eq. 3), so no exact solution leaves [-Ms, Ms]; a guarded step might.
    m = m.cwiseMax(-p_.Ms).cwiseMin(p_.Ms);
    H = (i + 1 == steps) ? H_target : H + h;
    state_ = {H, m[0], m[1]};
    if (!std::isfinite(m[0]) || !std::isfinite(m[1])) {
      ++recoveries_;
      settle_on_anhysteretic();
      m = Vec2(state_.M, state_.M_irr);
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
