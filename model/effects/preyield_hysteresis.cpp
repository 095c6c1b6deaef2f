#include "model/effects/preyield_hysteresis.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace mrd::model {

double PreyieldHysteresisParams::z_max() const { return std::pow(A / (beta + gamma), 1.0 / n); }

ValidationReport validate(const PreyieldHysteresisParams& p) {
  ValidationReport report;
  report.require_positive("A", p.A);
  report.require_positive("beta", p.beta);
  // -beta < gamma <= beta keeps z bounded (Ikhouane et al. 2007).
  if (!std::isfinite(p.gamma) || p.gamma <= -p.beta || p.gamma > p.beta) {
    report.error("gamma", "must lie in (-beta, beta] for a bounded z");
  }
  report.require_in_range("n", p.n, 1.0, 20.0, false);
  report.require_non_negative("stiffness", p.stiffness);
  report.require_in_range("yield_fraction", p.yield_fraction, 0.0, 1.0, false);
  if (p.max_substeps < 1 || p.max_substeps > 4096) {
    report.error("max_substeps", "must be in 1..4096, got " + std::to_string(p.max_substeps));
  }
  return report;
}

PreyieldHysteresis::PreyieldHysteresis(const PreyieldHysteresisParams& p, double sample_period)
    : A_(p.A),
      beta_(p.beta),
      gamma_(p.gamma),
      n_(p.n),
      square_(p.n == 2.0),
      stiffness_(p.stiffness),
      fraction_(p.yield_fraction),
      period_(sample_period),
      z_max_(p.z_max()),
      inv_z_max_(1.0 / z_max_),
      inv_max_substep_(2.0 * p.n * p.A / z_max_),
      max_substeps_(p.max_substeps) {}

double PreyieldHysteresis::slope(double z, double s) const {
  const double abs_z = std::fabs(z);
  const double z_n = square_ ? abs_z * abs_z : std::pow(abs_z, n_);  // |z|^n
  // beta |v| |z|^(n-1) z / v = s beta |z|^n sign(z)
  return A_ - (s * beta_ * (z >= 0.0 ? 1.0 : -1.0) + gamma_) * z_n;
}

double PreyieldHysteresis::step(double velocity) {
  const double dx = velocity * period_;
  if (dx == 0.0 || !std::isfinite(dx)) return z_;
  const double s = dx > 0.0 ? 1.0 : -1.0;
  const double travel = std::fabs(dx);
  const int substeps =
      static_cast<int>(std::clamp(std::ceil(travel * inv_max_substep_), 1.0, static_cast<double>(max_substeps_)));
  const double h = dx / substeps;
  double z = z_;
  for (int i = 0; i < substeps; ++i) {
    const double k1 = slope(z, s);
    const double k2 = slope(z + 0.5 * h * k1, s);
    const double k3 = slope(z + 0.5 * h * k2, s);
    const double k4 = slope(z + h * k3, s);
    z = std::clamp(z + h / 6.0 * (k1 + 2.0 * k2 + 2.0 * k3 + k4), -z_max_, z_max_);
  }
  z_ = std::isfinite(z) ? z : 0.0;
  return z_;
}

void PreyieldHysteresisEffect::apply(Params& p, std::span<const double> x, const RunScales&) {
  const double z_max = std::pow(10.0, x[1]);
  p.enabled = true;
  p.A = 1.0;
  p.n = 2.0;
  p.beta = p.gamma = 1.0 / (2.0 * z_max * z_max);
  p.stiffness = 0.0;
  p.yield_fraction = x[0];
}

std::optional<std::string> PreyieldHysteresisEffect::implausible(const Params& p, const RunScales&) {
  if (p.yield_fraction < 0.02) return "yield fraction below 2 %";
  return std::nullopt;
}

std::string PreyieldHysteresisEffect::size_summary(const Params& p) {
  char text[80];
  std::snprintf(text, sizeof text, "%.3g of the yield force on z, z_max = %.3g mm", p.yield_fraction,
                p.z_max() * 1e3);
  return text;
}

}  // namespace mrd::model
