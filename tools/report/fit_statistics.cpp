#include "tools/report/fit_statistics.hpp"

#include <Eigen/Dense>
#include <algorithm>
#include <cmath>
#include <limits>
#include <optional>

namespace mrd::tools {

double nrmse_fit_percent(const std::vector<double>& y, const std::vector<double>& yhat, const std::vector<bool>& keep) {
  constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
  if (y.size() != yhat.size() || y.empty() || (!keep.empty() && keep.size() != y.size())) return kNaN;
  const auto kept = [&](std::size_t i) { return keep.empty() || keep[i]; };
  double sum = 0.0;
  std::size_t n = 0;
  for (std::size_t i = 0; i < y.size(); ++i) {
    if (kept(i)) {
      sum += y[i];
      ++n;
    }
  }
  if (n == 0) return kNaN;
  const double mean = sum / static_cast<double>(n);
  double error = 0.0, spread = 0.0;
  for (std::size_t i = 0; i < y.size(); ++i) {
    if (!kept(i)) continue;
    error += (y[i] - yhat[i]) * (y[i] - yhat[i]);
    spread += (y[i] - mean) * (y[i] - mean);
  }
  if (spread <= 0.0) return kNaN;
  return 100.0 * (1.0 - std::sqrt(error) / std::sqrt(spread));
}

std::vector<double> autocorrelation(const std::vector<double>& e, std::size_t max_lag) {
  const std::size_t n = e.size();
  if (n == 0) return {};
  double mean = 0.0;
  for (const double x : e) mean += x;
  mean /= static_cast<double>(n);
  double energy = 0.0;
  for (const double x : e) energy += (x - mean) * (x - mean);
  std::vector<double> r(std::min(max_lag, n - 1) + 1, 0.0);
  if (energy <= 0.0) return r;
  for (std::size_t k = 0; k < r.size(); ++k) {
    double sum = 0.0;
    for (std::size_t i = 0; i + k < n; ++i) sum += (e[i] - mean) * (e[i + k] - mean);
    r[k] = sum / energy;
  }
  return r;
}

namespace {

// Two equally long series about their means: what both the cross-correlation and Bartlett's
// factor start from. nullopt when the lengths differ, a value is not finite, or either is constant.
struct CentredPair {
  double mean_u = 0.0, mean_e = 0.0;
  double energy_u = 0.0, energy_e = 0.0;  // sums of squares about the means
};
std::optional<CentredPair> centred_pair(const std::vector<double>& u, const std::vector<double>& e) {
  const std::size_t n = e.size();
  if (n < 2 || u.size() != n) return std::nullopt;
  CentredPair c;
  for (std::size_t i = 0; i < n; ++i) {
    if (!std::isfinite(u[i]) || !std::isfinite(e[i])) return std::nullopt;  // no figure rather than a wrong one
    c.mean_u += u[i];
    c.mean_e += e[i];
  }
  c.mean_u /= static_cast<double>(n);
  c.mean_e /= static_cast<double>(n);
  for (std::size_t i = 0; i < n; ++i) {
    c.energy_u += (u[i] - c.mean_u) * (u[i] - c.mean_u);
    c.energy_e += (e[i] - c.mean_e) * (e[i] - c.mean_e);
  }
  if (!(c.energy_u > 0.0) || !(c.energy_e > 0.0)) return std::nullopt;
  return c;
}

}  // namespace

std::vector<double> cross_correlation(const std::vector<double>& u, const std::vector<double>& e, std::size_t max_lag) {
  const auto c = centred_pair(u, e);
  if (!c) return {};
  const std::size_t n = e.size();
  const double mu = c->mean_u, me = c->mean_e;
  const std::size_t lags = std::min(max_lag, n - 1);
  std::vector<double> r(2 * lags + 1, 0.0);
  const double norm = std::sqrt(c->energy_u * c->energy_e);
  for (std::size_t k = 0; k <= lags; ++k) {
    double ahead = 0.0, behind = 0.0;  // e after u by k; e before u by k
    for (std::size_t i = 0; i + k < n; ++i) {
      ahead += (u[i] - mu) * (e[i + k] - me);
      behind += (u[i + k] - mu) * (e[i] - me);
    }
    r[lags + k] = ahead / norm;
    r[lags - k] = behind / norm;
  }
  return r;
}

double bartlett_factor(const std::vector<double>& u, const std::vector<double>& e) {
  const auto c = centred_pair(u, e);
  if (!c) return NAN;
  const std::size_t n = e.size();
  const double mu = c->mean_u, me = c->mean_e, uu = c->energy_u, ee = c->energy_e;
  const double noise = 1.96 / std::sqrt(static_cast<double>(n));
  double factor = 1.0;
  for (std::size_t m = 1; m <= n / 4; ++m) {
    double su = 0.0, se = 0.0;
    for (std::size_t i = 0; i + m < n; ++i) {
      su += (u[i] - mu) * (u[i + m] - mu);
      se += (e[i] - me) * (e[i + m] - me);
    }
    const double re = se / ee;
    if (std::abs(re) < noise) break;
    factor += 2.0 * (su / uu) * re;
  }
  return factor;
}

double autocorrelation_bound_95(std::size_t samples) {
  return samples > 0 ? 1.96 / std::sqrt(static_cast<double>(samples)) : 0.0;
}

// Relative to the largest pivot of the scaled Jacobian: below it a column is a combination of
// the others to within the central differences' accuracy.
constexpr double kRankTolerance = 1e-7;

ParameterUncertainty parameter_uncertainty(const ResidualFunction& residuals, const std::vector<double>& x,
                                           double relative_step) {
  const std::size_t p = x.size();
  const std::vector<double> r0 = residuals(x);
  const std::size_t n = r0.size();
  ParameterUncertainty out;
  out.samples = n;
  out.standard_deviation.assign(p, std::numeric_limits<double>::quiet_NaN());
  out.correlation.assign(p, std::vector<double>(p, std::numeric_limits<double>::quiet_NaN()));
  if (n <= p) {
    out.singular = true;
    return out;
  }
  Eigen::MatrixXd J(static_cast<Eigen::Index>(n), static_cast<Eigen::Index>(p));
  for (std::size_t j = 0; j < p; ++j) {
    const double h = relative_step * (x[j] != 0.0 ? std::abs(x[j]) : 1.0);
    std::vector<double> up = x, down = x;
    up[j] += h;
    down[j] -= h;
    const std::vector<double> r_up = residuals(up), r_down = residuals(down);
    for (std::size_t i = 0; i < n; ++i)
      J(static_cast<Eigen::Index>(i), static_cast<Eigen::Index>(j)) = (r_up[i] - r_down[i]) / (2.0 * h);
  }
  double ssr = 0.0;
  for (const double v : r0) ssr += v * v;
  const double variance = ssr / static_cast<double>(n - p);
  out.sigma = std::sqrt(variance);
  // A parameter the residual does not depend on at all (its column is zero: it acts on nothing
  // the data saw) has no standard deviation; the others are estimated without it.
  std::vector<Eigen::Index> used;
  for (Eigen::Index j = 0; j < J.cols(); ++j)
    if (J.col(j).norm() > 0.0) used.push_back(j);
  out.singular = used.size() < p;
  if (used.empty()) return out;
  // Scale the columns first: J-A parameters span ten orders of magnitude.
  const auto scaled_columns = [&](Eigen::MatrixXd& Js, Eigen::VectorXd& scale) {
    Js.resize(J.rows(), static_cast<Eigen::Index>(used.size()));
    scale.resize(static_cast<Eigen::Index>(used.size()));
    for (std::size_t u = 0; u < used.size(); ++u) {
      const auto iu = static_cast<Eigen::Index>(u);
      scale(iu) = J.col(used[u]).norm();
      Js.col(iu) = J.col(used[u]) / scale(iu);
    }
  };
  Eigen::MatrixXd Js;
  Eigen::VectorXd scale;
  scaled_columns(Js, scale);
  // Parameters that act only together with others (J's rank, by column-pivoted QR, falls short)
  // are not determined: those the pivoting puts last have none, the rest are estimated without
  // them.
  Eigen::ColPivHouseholderQR<Eigen::MatrixXd> qr(Js);
  qr.setThreshold(kRankTolerance);
  if (static_cast<std::size_t>(qr.rank()) < used.size()) {
    std::vector<Eigen::Index> determined;
    for (Eigen::Index k = 0; k < qr.rank(); ++k) determined.push_back(used[static_cast<std::size_t>(qr.colsPermutation().indices()(k))]);
    std::ranges::sort(determined);
    used = std::move(determined);
    out.singular = true;
    if (used.empty()) return out;
    scaled_columns(Js, scale);
  }
  const Eigen::FullPivLU<Eigen::MatrixXd> lu(Js.transpose() * Js);
  if (!lu.isInvertible()) {
    out.singular = true;
    return out;
  }
  const Eigen::MatrixXd scaled_cov = lu.inverse();
  for (std::size_t a = 0; a < used.size(); ++a) {
    const auto ia = static_cast<Eigen::Index>(a);
    const auto pa = static_cast<std::size_t>(used[a]);
    out.standard_deviation[pa] = out.sigma * std::sqrt(scaled_cov(ia, ia)) / scale(ia);
    for (std::size_t b = 0; b < used.size(); ++b) {
      const auto ib = static_cast<Eigen::Index>(b);
      out.correlation[pa][static_cast<std::size_t>(used[b])] =
          scaled_cov(ia, ib) / std::sqrt(scaled_cov(ia, ia) * scaled_cov(ib, ib));
    }
  }
  return out;
}

}  // namespace mrd::tools
