#include "tools/residual/least_squares_refine.hpp"

#include <Eigen/Cholesky>
#include <Eigen/Core>

#include <algorithm>
#include <cmath>
#include <limits>
#include <vector>

namespace mrd::tools {

namespace {

constexpr double kInitialDamping = 1e-3, kMaxDamping = 1e8;

// One observer pass's residuals at a point, with scratch of its own (one per worker).
struct Evaluator {
  const ParameterSpace& space;
  const FitSeries& series;
  std::vector<double> buffer;
  std::vector<double> residuals;

  // The sum of squares at p, +inf where the model fails validation.
  double operator()(const Point& p) {
    if (!space_residuals(space, series, p, buffer, residuals)) return std::numeric_limits<double>::infinity();
    double sum = 0.0;
    for (const double r : residuals) sum += r * r;
    return std::isfinite(sum) ? sum : std::numeric_limits<double>::infinity();
  }
};

Eigen::Map<const Eigen::VectorXd> as_vector(const std::vector<double>& v) {
  return {v.data(), static_cast<Eigen::Index>(v.size())};
}

}  // namespace

namespace {

// The iteration's state: the point, its residuals and their sum of squares, the damping.
class LevenbergMarquardt {
 public:
  LevenbergMarquardt(const ParameterSpace& space, const FitSeries& series, WorkerPool* pool, int max_evaluations)
      : space_(space),
        pool_(pool),
        max_evaluations_(max_evaluations),
        evaluators_(pool != nullptr ? pool->size() : 1, Evaluator{space, series, {}, {}}),
        range_(space.bounds.upper - space.bounds.lower) {}

  // False where the start itself fails validation.
  bool start(const Point& from) {
    x_ = space_.bounds.clamp(from);
    cost_ = evaluate(x_);
    if (!std::isfinite(cost_)) return false;
    r_ = as_vector(evaluators_.front().residuals);
    J_.resize(r_.size(), space_.bounds.dimension());
    return true;
  }

  // One Jacobian and the damped steps until one lowers the sum of squares; false when the
  // budget, the damping or the coordinates run out, or the fall is below the tolerance.
  bool iterate() {
    const Eigen::Index n = space_.bounds.dimension();
    if (evaluations_ + n + 1 > max_evaluations_) return false;
    const std::vector<Eigen::Index> free = free_coordinates(jacobian());
    if (free.empty()) return false;
    const auto k = static_cast<Eigen::Index>(free.size());
    const Eigen::MatrixXd normal = J_.transpose() * J_;
    const Eigen::VectorXd gradient = J_.transpose() * r_;
    Eigen::MatrixXd reduced(k, k);
    Eigen::VectorXd reduced_gradient(k);
    for (Eigen::Index a = 0; a < k; ++a) {
      reduced_gradient[a] = gradient[free[a]];
      for (Eigen::Index b = 0; b < k; ++b) reduced(a, b) = normal(free[a], free[b]);
    }
    const double floor = 1e-12 * std::max(reduced.diagonal().maxCoeff(), 1e-300);
    const Eigen::VectorXd scaling = reduced.diagonal().cwiseMax(floor);
    while (damping_ <= kMaxDamping && evaluations_ < max_evaluations_) {
      Eigen::MatrixXd damped = reduced;
      damped.diagonal() += damping_ * scaling;
      const Eigen::VectorXd step = -damped.ldlt().solve(reduced_gradient);
      Point trial = x_;
      for (Eigen::Index a = 0; a < k; ++a) trial[free[a]] += step[a];
      trial = space_.bounds.clamp(trial);
      const double trial_cost = evaluate(trial);
      // Nielsen's update: the damping follows how well the linear model predicted the fall.
      const double predicted = step.dot(damping_ * scaling.cwiseProduct(step) - reduced_gradient);
      if (trial_cost < cost_) {
        const double gain = predicted > 0.0 ? (cost_ - trial_cost) / predicted : 1.0;
        const double fall = cost_ - trial_cost;
        x_ = trial;
        cost_ = trial_cost;
        r_ = as_vector(evaluators_.front().residuals);
        damping_ *= std::max(1.0 / 3.0, 1.0 - std::pow(2.0 * std::min(gain, 1.0) - 1.0, 3));
        damping_ = std::max(damping_, 1e-12);
        growth_ = 2.0;
        return fall >= kLeastSquaresTolerance * cost_;
      }
      damping_ *= growth_;
      growth_ *= 2.0;
    }
    return false;
  }

  [[nodiscard]] const Point& point() const { return x_; }
  [[nodiscard]] std::int64_t evaluations() const { return evaluations_; }

 private:
  double evaluate(const Point& p) {
    ++evaluations_;
    return evaluators_.front()(p);
  }

  // J, a forward difference per coordinate stepped toward the interior; which columns are usable.
  std::vector<char> jacobian() {
    const Eigen::Index n = space_.bounds.dimension();
    std::vector<char> usable(static_cast<std::size_t>(n), 0);
    const auto column = [&](std::size_t j, unsigned worker) {
      const auto c = static_cast<Eigen::Index>(j);
      const double h = kJacobianStep * range_[c];
      Point p = x_;
      p[c] += (x_[c] + h <= space_.bounds.upper[c]) ? h : -h;
      const double step = p[c] - x_[c];
      Evaluator& e = evaluators_[worker];
      if (step == 0.0 || !std::isfinite(e(p))) {
        J_.col(c).setZero();
        return;
      }
      J_.col(c) = (as_vector(e.residuals) - r_) / step;
      usable[j] = 1;
    };
    if (pool_ != nullptr) pool_->run(static_cast<std::size_t>(n), column);
    else for (std::size_t j = 0; j < static_cast<std::size_t>(n); ++j) column(j, 0);
    evaluations_ += n;
    return usable;
  }

  // The usable coordinates but those on a bound that the slope pushes outward, which are held
  // there (a projected step): clamping them would shorten every other coordinate's step too.
  std::vector<Eigen::Index> free_coordinates(const std::vector<char>& usable) const {
    const Eigen::VectorXd gradient = J_.transpose() * r_;
    std::vector<Eigen::Index> free;
    for (Eigen::Index j = 0; j < space_.bounds.dimension(); ++j) {
      const bool pushed_down = x_[j] <= space_.bounds.lower[j] && gradient[j] > 0.0;
      const bool pushed_up = x_[j] >= space_.bounds.upper[j] && gradient[j] < 0.0;
      if (usable[static_cast<std::size_t>(j)] != 0 && !pushed_down && !pushed_up) free.push_back(j);
    }
    return free;
  }

  const ParameterSpace& space_;
  WorkerPool* pool_;
  int max_evaluations_;
  std::vector<Evaluator> evaluators_;  // one per worker; the first is the iteration's own
  Point range_;
  Point x_;
  double cost_ = 0.0;
  Eigen::VectorXd r_;
  Eigen::MatrixXd J_;
  double damping_ = kInitialDamping;
  double growth_ = 2.0;
  std::int64_t evaluations_ = 0;
};

}  // namespace

FittedModel refine_least_squares(const ParameterSpace& space, const FitSeries& series, const Point& start,
                                 int max_evaluations, WorkerPool* pool) {
  if (space.bounds.dimension() == 0) return fitted_at(space, series, Point(0), 1);
  LevenbergMarquardt lm(space, series, pool, max_evaluations);
  if (lm.start(start))
    while (lm.iterate()) {
    }
  return fitted_at(space, series, lm.point(), lm.evaluations() + 1);
}

}  // namespace mrd::tools
