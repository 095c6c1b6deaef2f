#pragma once

#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "tools/identification/bh_objective.hpp"
#include "tools/identification/polish.hpp"
#include "tools/optimisation/particle_swarm.hpp"
#include "tools/progress.hpp"

namespace mrd::tools {

enum class Algorithm { kPso, kImprovedPso, kPagmoPso, kPagmoDe, kPagmoSade, kPagmoCmaes };

// The algorithms this build has: the pagmo-* reference peers only where pagmo2 was found
// (MRD_HAVE_PAGMO; not in the arm64 build).
inline constexpr Algorithm kAllAlgorithms[] = {
    Algorithm::kPso, Algorithm::kImprovedPso,
#ifdef MRD_HAVE_PAGMO
    Algorithm::kPagmoPso, Algorithm::kPagmoDe, Algorithm::kPagmoSade, Algorithm::kPagmoCmaes,
#endif
};

std::string_view algorithm_name(Algorithm algorithm);  // the --algo spelling
std::optional<Algorithm> parse_algorithm(std::string_view name);  // only those of kAllAlgorithms
std::vector<std::string> algorithm_names();                       // of kAllAlgorithms, for --help

struct IdentifyOptions {
  Algorithm algorithm = Algorithm::kImprovedPso;
  Budget budget;
  std::uint64_t seed = 1;
  unsigned threads = 0;            // 0: all cores (our swarms; pagmo's run serially)
  std::optional<Point> start;      // default: estimate_start_point
  std::optional<Bounds> bounds;    // default: +-100% around the start
  // With an estimated start (no --start, no --bounds): when the best point ends on a face of
  // the +-100% box, the box moves to centre on it and the search runs again, up to this many
  // times. Each round spends the full budget; the result reports the total.
  int recentre_rounds = 3;
  bool polish = false;
  int polish_evaluations = 3000;
  ClassicalPsoSettings classical;
  ImprovedPsoSettings improved;
  ProgressSink* progress = nullptr;  // round, evaluations and best RMSE as the search goes
};

struct IdentifyResult {
  Algorithm algorithm = Algorithm::kImprovedPso;
  Point start;
  Bounds bounds;
  OptimisationResult search;  // the global search alone (all rounds)
  int rounds = 1;
  FitEvaluation fit{};        // at search.best
  double wall_s = 0.0;        // the global search's wall time
  std::optional<PolishResult> polish;
  double polish_wall_s = 0.0;
};

IdentifyResult identify(const BHObjective& objective, const BHCurve& curve,
                        const IdentifyOptions& options);

}  // namespace mrd::tools
