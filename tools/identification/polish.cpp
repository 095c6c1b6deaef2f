#include "tools/identification/polish.hpp"

#include <cmath>
#include <unsupported/Eigen/NonLinearOptimization>
#include <unsupported/Eigen/NumericalDiff>

namespace mrd::tools {

namespace {

struct Residuals {
  using Scalar = double;
  enum { InputsAtCompileTime = Eigen::Dynamic, ValuesAtCompileTime = Eigen::Dynamic };
  using InputType = Eigen::VectorXd;
  using ValueType = Eigen::VectorXd;
  using JacobianType = Eigen::MatrixXd;

  const BHObjective* objective;
  const Bounds* bounds;
  Point scale;
  mutable std::vector<double> B;
  mutable std::int64_t evaluations = 0;

  [[nodiscard]] int inputs() const { return static_cast<int>(scale.size()); }
  [[nodiscard]] int values() const { return static_cast<int>(objective->points()); }
  [[nodiscard]] Point to_x(const Eigen::VectorXd& z) const {
    return bounds->clamp(z.cwiseProduct(scale));
  }

  int operator()(const Eigen::VectorXd& z, Eigen::VectorXd& residual) const {
    ++evaluations;
    const FitEvaluation fit = objective->evaluate(to_x(z), B);
    const auto measured = objective->measured_B();
    const double n = static_cast<double>(measured.size());
    // A penalised point gets its penalty spread over all residuals, so ||r||^2 = fitness^2.
    const double extra = fit.penalised ? fit.fitness : 0.0;
    for (Eigen::Index i = 0; i < residual.size(); ++i) {
      const auto k = static_cast<std::size_t>(i);
      const double r = fit.penalised && !std::isfinite(fit.rmse) ? 0.0 : B[k] - measured[k];
      residual[i] = (r + extra) / std::sqrt(n);
    }
    return 0;
  }
};

}  // namespace

PolishResult polish_levenberg_marquardt(const BHObjective& objective, const Point& start,
                                        const Bounds& bounds, int max_evaluations) {
  Residuals functor{&objective, &bounds, start.cwiseAbs().cwiseMax(1e-12), {}, 0};
  functor.B.resize(objective.points());
  Eigen::NumericalDiff<Residuals> with_jacobian(functor, 1e-7);
  Eigen::LevenbergMarquardt<Eigen::NumericalDiff<Residuals>> lm(with_jacobian);
  lm.parameters.maxfev = max_evaluations / (static_cast<int>(start.size()) + 1);
  lm.parameters.xtol = 1e-12;
  lm.parameters.ftol = 1e-14;
  Eigen::VectorXd z = Eigen::VectorXd::Ones(start.size());
  const auto status = lm.minimize(z);

  PolishResult result;
  const Point x = functor.to_x(z);
  const FitEvaluation polished = objective.evaluate(to_params(x));
  const FitEvaluation original = objective.evaluate(to_params(start));
  // LM only ever accepts improving steps, but clamping can mislead it: keep the better point.
  const bool improved = polished.fitness <= original.fitness;
  result.best = improved ? x : start;
  result.rmse = improved ? polished.rmse : original.rmse;
  result.evaluations = with_jacobian.evaluations + 2;
  result.status = static_cast<int>(status);
  return result;
}

}  // namespace mrd::tools
