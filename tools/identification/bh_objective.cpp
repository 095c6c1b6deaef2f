#include "tools/identification/bh_objective.hpp"

#include <cmath>
#include <limits>

namespace mrd::tools {

model::JilesAthertonParams to_params(const Point& x) { return {x[0], x[1], x[2], x[3], x[4]}; }

Point to_point(const model::JilesAthertonParams& p) {
  Point x(kParameterCount);
  x << p.Ms, p.a, p.alpha, p.k, p.c;
  return x;
}

namespace {
// The physical ranges of model::validate, without its messages (this runs per evaluation).
bool simulatable(const model::JilesAthertonParams& p) {
  const bool finite = std::isfinite(p.Ms) && std::isfinite(p.a) && std::isfinite(p.alpha) &&
                      std::isfinite(p.k) && std::isfinite(p.c);
  return finite && p.Ms > 0.0 && p.a > 0.0 && p.k > 0.0 && p.alpha >= 0.0 && p.c >= 0.0 &&
         p.c < 1.0;
}
}  // namespace

BHObjective::BHObjective(const BHCurve& curve, const model::JilesAthertonSettings& settings)
    : simulator_(curve), settings_(settings), rms_B_(curve.rms_B()) {}

FitEvaluation BHObjective::evaluate(const Point& x, std::span<double> scratch,
                                    double cutoff) const {
  const auto p = to_params(x);
  if (!simulatable(p)) {
    return {kInvalidFitness * rms_B_, std::numeric_limits<double>::infinity(), true};
  }
  const double n = static_cast<double>(points());
  // fitness >= rmse, so a squared error above n cutoff^2 already loses.
  const double squared_cutoff = std::isfinite(cutoff) ? n * cutoff * cutoff : cutoff;
  const SimulationStats stats = simulator_.simulate(p, scratch, settings_, squared_cutoff);
  const double rmse = std::sqrt(stats.squared_error / n);  // Eq. 15
  if (stats.abandoned) return {rmse, rmse, false};
  if (stats.guard_events == 0 && stats.recoveries == 0 && std::isfinite(rmse)) {
    return {rmse, rmse, false};
  }
  const double guarded = static_cast<double>(stats.guard_events + stats.recoveries) /
                         n;
  const double penalty = rms_B_ * (1.0 + std::min(guarded, 1.0));
  return {(std::isfinite(rmse) ? rmse : kInvalidFitness * rms_B_) + penalty, rmse, true};
}

FitEvaluation BHObjective::evaluate(const model::JilesAthertonParams& p) const {
  std::vector<double> scratch(points());
  return evaluate(to_point(p), scratch);
}

std::vector<double> BHObjective::simulate(const model::JilesAthertonParams& p) const {
  std::vector<double> B(points());
  simulator_.simulate(p, B, settings_);
  return B;
}

ParallelBHObjective::ParallelBHObjective(const BHObjective& objective, WorkerPool& pool)
    : objective_(objective), pool_(pool), scratch_(pool.size()) {
  for (auto& s : scratch_) s.resize(objective.points());
}

void ParallelBHObjective::evaluate(const std::vector<Point>& points, std::vector<double>& fitness,
                                   const std::vector<double>* cutoffs) {
  fitness.resize(points.size());
  pool_.run(points.size(), [&](std::size_t i, unsigned worker) {
    const double cutoff = cutoffs ? (*cutoffs)[i] : std::numeric_limits<double>::infinity();
    fitness[i] = objective_.evaluate(points[i], scratch_[worker], cutoff).fitness;
  });
  evaluations_ += static_cast<std::int64_t>(points.size());
}

}  // namespace mrd::tools
