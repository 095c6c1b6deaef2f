#include "tools/identification/identification.hpp"

#include <algorithm>
#include <chrono>

#include "tools/identification/pagmo_peers.hpp"
#include "tools/identification/start_point.hpp"

namespace mrd::tools {

namespace {
struct AlgorithmName {
  Algorithm algorithm;
  std::string_view name;
};
constexpr AlgorithmName kNames[] = {
    {Algorithm::kPso, "pso"},          {Algorithm::kImprovedPso, "improved-pso"},
    {Algorithm::kPagmoPso, "pagmo-pso"}, {Algorithm::kPagmoDe, "pagmo-de"},
    {Algorithm::kPagmoSade, "pagmo-sade"}, {Algorithm::kPagmoCmaes, "pagmo-cmaes"}};

double seconds_since(std::chrono::steady_clock::time_point start) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

}  // namespace

std::string_view algorithm_name(Algorithm algorithm) {
  for (const auto& n : kNames) {
    if (n.algorithm == algorithm) return n.name;
  }
  return "?";
}

std::optional<Algorithm> parse_algorithm(std::string_view name) {
  for (const auto& n : kNames) {
    if (n.name == name) return n.algorithm;
  }
  return std::nullopt;
}

namespace {

OptimisationResult run_search(const BHObjective& objective, const Bounds& bounds,
                              const IdentifyOptions& options, std::uint64_t seed) {
  switch (options.algorithm) {
    case Algorithm::kPso:
    case Algorithm::kImprovedPso: {
      WorkerPool pool(options.threads);
      ParallelBHObjective parallel(objective, pool);
      return options.algorithm == Algorithm::kPso
                 ? run_classical_pso(parallel, bounds, options.budget, options.classical, seed)
                 : run_improved_pso(parallel, bounds, options.budget, options.improved, seed);
    }
    case Algorithm::kPagmoPso:
      return run_pagmo(PagmoAlgorithm::kPso, objective, bounds, options.budget, seed);
    case Algorithm::kPagmoDe:
      return run_pagmo(PagmoAlgorithm::kDe, objective, bounds, options.budget, seed);
    case Algorithm::kPagmoSade:
      return run_pagmo(PagmoAlgorithm::kSade, objective, bounds, options.budget, seed);
    case Algorithm::kPagmoCmaes:
      return run_pagmo(PagmoAlgorithm::kCmaes, objective, bounds, options.budget, seed);
  }
  return {};
}

}  // namespace

IdentifyResult identify(const BHObjective& objective, const BHCurve& curve,
                        const IdentifyOptions& options) {
  IdentifyResult result;
  result.algorithm = options.algorithm;
  result.start = options.start ? *options.start : estimate_start_point(curve);
  result.bounds = options.bounds ? *options.bounds : bounds_around(result.start);

  const auto started = std::chrono::steady_clock::now();
  const bool may_recentre = !options.start && !options.bounds;
  Bounds bounds = result.bounds;
  Point centre = result.start;
  for (int round = 0;; ++round) {
    OptimisationResult search = run_search(objective, bounds, options, options.seed + 7919u * round);
    if (round == 0 || search.fitness < result.search.fitness) {
      const auto spent = result.search.evaluations;
      auto trace = std::move(result.search.convergence);
      for (auto& c : search.convergence) c.evaluations += spent;
      trace.insert(trace.end(), search.convergence.begin(), search.convergence.end());
      result.search = std::move(search);
      result.search.evaluations += spent;
      result.search.convergence = std::move(trace);
      result.bounds = bounds;
    } else {
      result.search.evaluations += search.evaluations;
    }
    result.rounds = round + 1;
    const auto hit = on_estimated_face(result.search.best, bounds, centre);
    if (!may_recentre || round >= options.recentre_rounds ||
        std::none_of(hit.begin(), hit.end(), [](bool h) { return h; })) {
      break;
    }
    // Only the parameters that hit a face move their box; the others keep theirs, so a
    // parameter whose best is near zero does not get its box shrunk onto zero.
    const Bounds moved = bounds_around(result.search.best);
    for (int j = 0; j < kParameterCount; ++j) {
      if (!hit[static_cast<std::size_t>(j)]) continue;
      bounds.lower[j] = moved.lower[j];
      bounds.upper[j] = moved.upper[j];
      centre[j] = result.search.best[j];
    }
  }
  result.wall_s = seconds_since(started);
  result.fit = objective.evaluate(to_params(result.search.best));

  if (options.polish) {
    const auto polish_started = std::chrono::steady_clock::now();
    result.polish = polish_levenberg_marquardt(objective, result.search.best, result.bounds,
                                               options.polish_evaluations);
    result.polish_wall_s = seconds_since(polish_started);
  }
  return result;
}

}  // namespace mrd::tools
