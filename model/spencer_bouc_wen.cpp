#include "model/spencer_bouc_wen.hpp"

#include <algorithm>
#include <cmath>

namespace mrd::model {

SpencerBoucWenParams SpencerBoucWenParams::dyke_prototype() {
  SpencerBoucWenParams p;
  p.c0a = 21.0 * 100.0;      // N s/cm -> N s/m
  p.c0b = 3.5 * 100.0;
  p.k0 = 46.9 * 100.0;       // N/cm -> N/m
  p.c1a = 283.0 * 100.0;
  p.c1b = 2.95 * 100.0;
  p.k1 = 5.0 * 100.0;
  p.x0 = 14.3 / 100.0;       // cm -> m
  p.alpha_a = 140.0 * 100.0;
  p.alpha_b = 695.0 * 100.0;
  p.gamma = 363.0 * 1e4;     // cm^-2 -> m^-2
  p.beta = 363.0 * 1e4;
  p.A = 301.0;
  p.n = 2.0;
  p.eta = 190.0;
  return p;
}

ValidationReport validate(const SpencerBoucWenParams& p) {
  ValidationReport report;
  report.require_non_negative("c0a", p.c0a);
  report.require_non_negative("c0b", p.c0b);
  report.require_non_negative("k0", p.k0);
  report.require_non_negative("c1a", p.c1a);
  report.require_non_negative("c1b", p.c1b);
  report.require_non_negative("k1", p.k1);
  if (!std::isfinite(p.x0)) report.error("x0", "must be finite");
  report.require_non_negative("alpha_a", p.alpha_a);
  report.require_non_negative("alpha_b", p.alpha_b);
  report.require_positive("beta", p.beta);
  if (!std::isfinite(p.gamma) || p.gamma <= -p.beta || p.gamma > p.beta) {
    report.error("gamma", "must lie in (-beta, beta] for a bounded z");
  }
  report.require_positive("A", p.A);
  report.require_in_range("n", p.n, 1.0, 20.0, false);
  report.require_positive("eta", p.eta);
  if (report.ok() && p.c0a + p.c1a <= 0.0) report.error("c1a", "c0a + c1a must be > 0");
  return report;
}

SpencerBoucWen::SpencerBoucWen(const SpencerBoucWenParams& params, double sample_period, int max_substeps)
    : p_(params),
      period_(sample_period),
      max_substeps_(std::max(max_substeps, 1)),
      z_max_(std::pow(params.A / (params.beta + params.gamma), 1.0 / params.n)) {}

void SpencerBoucWen::reset(double displacement) {
  state_ = {displacement, 0.0, 0.0};
  last_x_ = displacement;
  last_xdot_ = 0.0;
  primed_ = true;
}

std::pair<double, double> SpencerBoucWen::ydot_c1(const SpencerBoucWenState& s, double x, double xdot) const {
  const double alpha = p_.alpha_a + p_.alpha_b * s.u;
  const double c0 = p_.c0a + p_.c0b * s.u;
  const double c1 = p_.c1a + p_.c1b * s.u;
  return {(alpha * s.z + c0 * xdot + p_.k0 * (x - s.y)) / (c0 + c1), c1};
}

SpencerBoucWen::Rates SpencerBoucWen::rates(const SpencerBoucWenState& s, double x, double xdot,
                                            double voltage) const {
  const double ydot = ydot_c1(s, x, xdot).first;
  const double rel = xdot - ydot;
  const double abs_z = std::fabs(s.z);
  const double z_n = p_.n == 2.0 ? abs_z * abs_z : std::pow(abs_z, p_.n);
  // gamma |rel| z |z|^(n-1) = gamma |rel| sign(z) |z|^n
  const double zdot = -p_.gamma * std::fabs(rel) * (s.z >= 0.0 ? z_n : -z_n) - p_.beta * rel * z_n + p_.A * rel;
  return {ydot, zdot, -p_.eta * (s.u - voltage)};
}

double SpencerBoucWen::step(const SpencerBoucWenInput& sample) {
  const double x = sample.displacement;
  const double xdot = sample.velocity;
  const double voltage = sample.command_voltage;
  if (!primed_) reset(x);
  const double x_start = last_x_;
  const double v_start = last_xdot_;
  last_x_ = x;
  last_xdot_ = xdot;
  // Sub-steps from the rate bound in the class comment: |x' - y'| <= |x'| + |y'|, with y' taken
  // at the start of the period (y' moves little within one).
  const double u_max = std::max(std::fabs(state_.u), std::fabs(voltage));
  const double alpha = p_.alpha_a + p_.alpha_b * u_max;
  const double damping = p_.c0a + p_.c1a;  // the smallest c0 + c1 (u >= 0)
  const double ydot = std::fabs(rates(state_, x_start, v_start, voltage).y);
  const double speed = std::max(std::fabs(v_start), std::fabs(xdot)) + ydot;
  const double rate = p_.n * p_.A * speed / z_max_ + p_.A * alpha / damping + p_.eta;
  const int substeps =
      static_cast<int>(std::clamp(std::ceil(2.0 * rate * period_), 1.0, static_cast<double>(max_substeps_)));
  const double h = period_ / substeps;
  SpencerBoucWenState s = state_;
  for (int i = 0; i < substeps; ++i) {
    const double f0 = static_cast<double>(i) / substeps;
    const double fm = (i + 0.5) / substeps;
    const double f1 = static_cast<double>(i + 1) / substeps;
    const auto at = [&](double f) { return std::pair{x_start + f * (x - x_start), v_start + f * (xdot - v_start)}; };
    const auto [xa, va] = at(f0);
    const auto [xm, vm] = at(fm);
    const auto [xb, vb] = at(f1);
    const Rates k1 = rates(s, xa, va, voltage);
    const Rates k2 = rates({s.y + 0.5 * h * k1.y, s.z + 0.5 * h * k1.z, s.u + 0.5 * h * k1.u}, xm, vm, voltage);
    const Rates k3 = rates({s.y + 0.5 * h * k2.y, s.z + 0.5 * h * k2.z, s.u + 0.5 * h * k2.u}, xm, vm, voltage);
    const Rates k4 = rates({s.y + h * k3.y, s.z + h * k3.z, s.u + h * k3.u}, xb, vb, voltage);
    s.y += h / 6.0 * (k1.y + 2.0 * k2.y + 2.0 * k3.y + k4.y);
    s.z = std::clamp(s.z + h / 6.0 * (k1.z + 2.0 * k2.z + 2.0 * k3.z + k4.z), -z_max_, z_max_);
    s.u += h / 6.0 * (k1.u + 2.0 * k2.u + 2.0 * k3.u + k4.u);
  }
  if (std::isfinite(s.y) && std::isfinite(s.z) && std::isfinite(s.u)) state_ = s;
  const auto [ydot_end, c1] = ydot_c1(state_, x, xdot);
  return c1 * ydot_end + p_.k1 * (x - p_.x0);
}

}  // namespace mrd::model
