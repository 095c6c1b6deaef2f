#include "tools/identification/pagmo_peers.hpp"

#include <limits>
#include <memory>
#include <pagmo/algorithm.hpp>
#include <pagmo/algorithms/cmaes.hpp>
#include <pagmo/algorithms/de.hpp>
#include <pagmo/algorithms/pso.hpp>
#include <pagmo/algorithms/sade.hpp>
#include <pagmo/population.hpp>
#include <pagmo/problem.hpp>

namespace mrd::tools {

namespace {

// Best-so-far after each evaluation, for the convergence curve.
struct Recorder {
  std::int64_t evaluations = 0;
  double best = std::numeric_limits<double>::infinity();
  Point best_x;
  std::vector<ConvergencePoint> trace;
  int population = 30;
};

// pagmo copies problems, so the objective and the recorder are shared by pointer.
struct PagmoProblem {
  const BHObjective* objective = nullptr;
  std::shared_ptr<Recorder> recorder;
  Bounds bounds;

  [[nodiscard]] pagmo::vector_double fitness(const pagmo::vector_double& x) const {
    thread_local std::vector<double> scratch;
    scratch.resize(objective->points());
    const Point p = Eigen::Map<const Point>(x.data(), static_cast<Eigen::Index>(x.size()));
    const double f = objective->evaluate(p, scratch).fitness;
    auto& r = *recorder;
    ++r.evaluations;
    if (f < r.best) {
      r.best = f;
      r.best_x = p;
    }
    if (r.evaluations % r.population == 0) r.trace.push_back({r.evaluations, r.best});
    return {f};
  }
  [[nodiscard]] std::pair<pagmo::vector_double, pagmo::vector_double> get_bounds() const {
    return {{bounds.lower.data(), bounds.lower.data() + bounds.lower.size()},
            {bounds.upper.data(), bounds.upper.data() + bounds.upper.size()}};
  }
};

pagmo::algorithm make_algorithm(PagmoAlgorithm algorithm, unsigned generations, unsigned seed) {
  // Tolerances 0: every algorithm spends the whole budget, as ours do.
  switch (algorithm) {
    case PagmoAlgorithm::kPso:
      return pagmo::algorithm{pagmo::pso(generations, 0.7298, 2.05, 2.05, 0.5, 5u, 2u, 4u, false, seed)};
    case PagmoAlgorithm::kDe:
      return pagmo::algorithm{pagmo::de(generations, 0.8, 0.9, 2u, 0.0, 0.0, seed)};
    case PagmoAlgorithm::kSade:
      return pagmo::algorithm{pagmo::sade(generations, 2u, 1u, 0.0, 0.0, false, seed)};
    case PagmoAlgorithm::kCmaes:
      return pagmo::algorithm{
          pagmo::cmaes(generations, -1, -1, -1, -1, 0.5, 0.0, 0.0, false, true, seed)};
  }
  return pagmo::algorithm{};
}

}  // namespace

OptimisationResult run_pagmo(PagmoAlgorithm algorithm, const BHObjective& objective,
                             const Bounds& bounds, const Budget& budget, std::uint64_t seed) {
  auto recorder = std::make_shared<Recorder>();
  recorder->population = budget.population;
  pagmo::problem problem{PagmoProblem{&objective, recorder, bounds}};
  const auto seed32 = static_cast<unsigned>(seed ^ (seed >> 32));
  pagmo::population population{problem, static_cast<pagmo::population::size_type>(budget.population),
                               seed32};
  const auto generations =
      static_cast<unsigned>((budget.evaluations - budget.population) / budget.population);
  make_algorithm(algorithm, generations, seed32).evolve(population);

  OptimisationResult result;
  result.best = recorder->best_x;
  result.fitness = recorder->best;
  result.evaluations = recorder->evaluations;
  result.convergence = recorder->trace;
  return result;
}

}  // namespace mrd::tools
