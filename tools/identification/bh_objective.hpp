#pragma once

#include <array>
#include <limits>
#include <span>
#include <string_view>
#include <vector>

#include "tools/identification/loop_simulation.hpp"
#include "tools/optimisation/optimiser.hpp"
#include "tools/optimisation/worker_pool.hpp"

namespace mrd::tools {

// The search vector is (Ms, a, alpha, k, c) in SI units.
inline constexpr int kParameterCount = 5;
inline constexpr std::array<std::string_view, kParameterCount> kParameterNames{"Ms", "a", "alpha",
                                                                               "k", "c"};
model::JilesAthertonParams to_params(const Point& x);
Point to_point(const model::JilesAthertonParams& p);

struct FitEvaluation {
  double fitness;  // rmse, plus a penalty when the parameters are non-physical
  double rmse;     // Eq. 15 [T]; infinite when the parameters could not be simulated
  bool penalised;
};

// Eq. 15 over every point of every loop. Parameters outside physics (Ms, a, k <= 0,
// alpha < 0, c outside [0, 1)) are not simulated: their fitness is kInvalidFitness x rms(B).
// Parameters that make Eq. 10 run away (its guard fired) or go non-finite are simulated and
// pay rms(B) x (1 + guarded fraction of steps) on top of their RMSE, so the search leaves
// them without losing its sense of direction.
class BHObjective {
 public:
  static constexpr double kInvalidFitness = 10.0;

  explicit BHObjective(const BHCurve& curve, const model::JilesAthertonSettings& settings = {});

  [[nodiscard]] std::size_t points() const { return simulator_.points(); }
  [[nodiscard]] double rms_B() const { return rms_B_; }
  [[nodiscard]] std::span<const double> measured_B() const { return simulator_.measured_B(); }

  // Allocation-free: `scratch` holds points() values. With a finite `cutoff` on the fitness,
  // a point that cannot beat it stops early and reports a fitness above the cutoff.
  FitEvaluation evaluate(const Point& x, std::span<double> scratch,
                         double cutoff = std::numeric_limits<double>::infinity()) const;
  FitEvaluation evaluate(const model::JilesAthertonParams& p) const;
  [[nodiscard]] std::vector<double> simulate(const model::JilesAthertonParams& p) const;

 private:
  LoopSimulator simulator_;
  model::JilesAthertonSettings settings_;
  double rms_B_;
};

// BHObjective over a WorkerPool; counts every evaluation.
class ParallelBHObjective final : public BatchObjective {
 public:
  ParallelBHObjective(const BHObjective& objective, WorkerPool& pool);
  void evaluate(const std::vector<Point>& points, std::vector<double>& fitness,
                const std::vector<double>* cutoffs = nullptr) override;
  [[nodiscard]] std::int64_t evaluations() const { return evaluations_; }

 private:
  const BHObjective& objective_;
  WorkerPool& pool_;
  std::vector<std::vector<double>> scratch_;  // one per worker
  std::int64_t evaluations_ = 0;
};

}  // namespace mrd::tools
