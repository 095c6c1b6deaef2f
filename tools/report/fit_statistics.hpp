#pragma once

#include <functional>
#include <string>
#include <vector>

// The figures an engineer expects beside a fitted model, as MATLAB's System Identification
// Toolbox gives them (compare, resid, present).
namespace mrd::tools {

// NRMSE fit [%] as compare() defines it: 100 (1 - |y - yhat| / |y - mean(y)|), Euclidean norms.
// 100 is a perfect fit, 0 no better than the mean, negative worse. NaN when y is constant or
// the lengths differ. Samples where `keep` is given and false are left out.
[[nodiscard]] double nrmse_fit_percent(const std::vector<double>& y, const std::vector<double>& yhat,
                                       const std::vector<bool>& keep = {});

// Normalised autocorrelation r(k) = sum e_i e_{i+k} / sum e_i^2 of a residual (mean removed),
// lags 0..max_lag; r(0) = 1. For white noise |r(k)| stays within +-1.96/sqrt(N) at 95 %.
[[nodiscard]] std::vector<double> autocorrelation(const std::vector<double>& residual, std::size_t max_lag);
[[nodiscard]] double autocorrelation_bound_95(std::size_t samples);

// Normalised cross-correlation of an input u and a residual e (means removed), as MATLAB's resid
// shows it: r(k) = sum u_i e_{i+k} / sqrt(sum u^2 sum e^2) for k = -max_lag..max_lag, at index
// k + max_lag. A model that leaves nothing of u unexplained keeps |r(k)| within 1.96/sqrt(N) at
// 95 % (e white); a peak at k > 0 is an effect of u that the residual shows k samples later.
// Empty when the lengths differ, a value is not finite, or either is constant.
[[nodiscard]] std::vector<double> cross_correlation(const std::vector<double>& u, const std::vector<double>& e,
                                                    std::size_t max_lag);

// Bartlett's factor S = 1 + 2 sum_m ru(m) re(m) on the variance S/N of a cross-correlation
// estimate between two unrelated series u and e (what MATLAB's resid widens its band by): summed
// until e's autocorrelation falls to its own noise (1.96/sqrt(N)), at most N/4 lags. 1 when e is
// white; large for two smooth series. NaN when the lengths differ, a value is not finite, or
// either is constant.
[[nodiscard]] double bartlett_factor(const std::vector<double>& u, const std::vector<double>& e);

// Parameter standard deviations of a least-squares fit at its optimum x: the covariance
// sigma^2 (J^T J)^-1 with sigma^2 = |r|^2 / (N - p) and J = dr/dx by central differences
// (step: relative_step |x_j|, or relative_step where x_j = 0). `residuals` maps parameters to
// the residual vector (any fixed length N > p).
struct ParameterUncertainty {
  std::vector<double> standard_deviation;  // per parameter; NaN where the data cannot determine it
  std::vector<std::vector<double>> correlation;
  double sigma = 0.0;  // residual standard error, sqrt(|r|^2 / (N - p))
  std::size_t samples = 0;
  // Some parameter the data cannot determine: one the residual does not depend on, or one that
  // acts only in a combination with others (J's rank falls short: the pivoted QR's last
  // columns); those are NaN and the others are estimated without them.
  bool singular = false;
};
using ResidualFunction = std::function<std::vector<double>(const std::vector<double>&)>;
[[nodiscard]] ParameterUncertainty parameter_uncertainty(const ResidualFunction& residuals,
                                                         const std::vector<double>& x,
                                                         double relative_step = 1e-4);

}  // namespace mrd::tools
