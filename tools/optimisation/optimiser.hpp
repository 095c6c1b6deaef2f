#pragma once

#include <Eigen/Core>
#include <cstdint>
#include <vector>

namespace mrd::tools {

using Point = Eigen::VectorXd;

struct Bounds {
  Point lower;
  Point upper;

  [[nodiscard]] Eigen::Index dimension() const { return lower.size(); }
  [[nodiscard]] Point clamp(const Point& x) const { return x.cwiseMax(lower).cwiseMin(upper); }
};

// Fitness of a batch of points, lower is better. Implementations may evaluate in parallel;
// the result must not depend on the order or the thread count.
//
// cutoffs[i] (optional, same size as points) says the caller only needs to know whether
// point i beats cutoffs[i]: a point that cannot may stop early and report any fitness above
// its cutoff. Selection and convergence are the same as with full evaluations.
class BatchObjective {
 public:
  virtual ~BatchObjective() = default;
  virtual void evaluate(const std::vector<Point>& points, std::vector<double>& fitness,
                        const std::vector<double>* cutoffs = nullptr) = 0;
};

struct Budget {
  int population = 30;
  std::int64_t evaluations = 4500;  // the paper's 30 x 150
};

struct ConvergencePoint {
  std::int64_t evaluations;
  double best_fitness;
};

struct OptimisationResult {
  Point best;
  double fitness = 0.0;
  std::int64_t evaluations = 0;
  std::vector<ConvergencePoint> convergence;  // after each iteration (Figure 8)
  int cauchy_trials = 0;    // improved PSO only
  int cauchy_accepted = 0;
};

}  // namespace mrd::tools
