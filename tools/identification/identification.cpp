#include "tools/identification/identification.hpp"

#include <algorithm>
#include <chrono>
#include <limits>
#include <string>

#ifdef MRD_HAVE_PAGMO
#include "tools/identification/pagmo_peers.hpp"
#endif
#include <stdexcept>
#include "tools/identification/start_point.hpp"
#include "tools/text_format.hpp"

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
  for (const Algorithm a : kAllAlgorithms) {
    if (algorithm_name(a) == name) return a;
  }
  return std::nullopt;
}

std::vector<std::string> algorithm_names() {
  std::vector<std::string> names;
  for (const Algorithm a : kAllAlgorithms) names.emplace_back(algorithm_name(a));
  return names;
}

namespace {

// Passes each batch to the objective and tells the progress sink the evaluations spent and the
// best fitness (RMSE of B) seen in this round.
class ReportingObjective final : public BatchObjective {
 public:
  ReportingObjective(BatchObjective& inner, ProgressSink& sink, const IdentifyOptions& options, int round,
                     std::string label)
      : inner_(inner), sink_(sink), options_(options), round_(round), label_(std::move(label)) {}
  void evaluate(const std::vector<Point>& points, std::vector<double>& fitness,
                const std::vector<double>* cutoffs) override {
    inner_.evaluate(points, fitness, cutoffs);
    evaluations_ += static_cast<std::int64_t>(points.size());
    for (const double f : fitness) best_ = std::min(best_, f);
    sink_.report({.stage = "box", .round = round_, .candidate = label_, .done = evaluations_, .total = options_.budget.evaluations, .best_error = best_,
                  .unit = "T RMSE"});
  }

 private:
  BatchObjective& inner_;
  ProgressSink& sink_;
  const IdentifyOptions& options_;
  int round_;
  std::string label_;
  std::int64_t evaluations_ = 0;
  double best_ = std::numeric_limits<double>::infinity();
};

// `boxes`: how many boxes the search may take at most (re-centred on a face), for the progress line.
OptimisationResult run_search(const BHObjective& objective, const Bounds& bounds,
                              const IdentifyOptions& options, std::uint64_t seed, int round, int boxes) {
  const std::string label = boxes > 1 ? format("%s, of at most %d boxes", std::string(algorithm_name(options.algorithm)).c_str(), boxes)
                                      : std::string(algorithm_name(options.algorithm));
  if (options.progress != nullptr)
    options.progress->report({.stage = "box", .round = round, .candidate = label, .total = options.budget.evaluations});
  switch (options.algorithm) {
    case Algorithm::kPso:
    case Algorithm::kImprovedPso: {
      WorkerPool pool(options.threads);
      ParallelBHObjective parallel(objective, pool);
      std::optional<ReportingObjective> reporting;
      if (options.progress != nullptr) reporting.emplace(parallel, *options.progress, options, round, label);
      BatchObjective& batch = reporting ? static_cast<BatchObjective&>(*reporting) : parallel;
      return options.algorithm == Algorithm::kPso
                 ? run_classical_pso(batch, bounds, options.budget, options.classical, seed)
                 : run_improved_pso(batch, bounds, options.budget, options.improved, seed);
    }
#ifdef MRD_HAVE_PAGMO
    case Algorithm::kPagmoPso:
      return run_pagmo(PagmoAlgorithm::kPso, objective, bounds, options.budget, seed);
    case Algorithm::kPagmoDe:
      return run_pagmo(PagmoAlgorithm::kDe, objective, bounds, options.budget, seed);
    case Algorithm::kPagmoSade:
      return run_pagmo(PagmoAlgorithm::kSade, objective, bounds, options.budget, seed);
    case Algorithm::kPagmoCmaes:
      return run_pagmo(PagmoAlgorithm::kCmaes, objective, bounds, options.budget, seed);
#else
    case Algorithm::kPagmoPso:
    case Algorithm::kPagmoDe:
    case Algorithm::kPagmoSade:
    case Algorithm::kPagmoCmaes:
      throw std::invalid_argument("this build has no pagmo2: " + std::string(algorithm_name(options.algorithm)));
#endif
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
    OptimisationResult search = run_search(objective, bounds, options, options.seed + 7919u * round, round + 1,
                                           may_recentre ? options.recentre_rounds + 1 : 1);
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
