// Identification at the paper's budget (population 30 x 150 iterations = 4,500 evaluations)
// on a 1,000-point curve, ours against pagmo2's on the same objective. Wall time counts:
// our swarms evaluate in parallel on all cores, pagmo's algorithms serially.
#include <benchmark/benchmark.h>

#include "tools/identification/identification.hpp"
#include "tools/identification/synthetic_curve.hpp"

namespace {

using namespace mrd::tools;

const mrd::model::JilesAthertonParams kSteel{1.6e6, 1100.0, 1.6e-3, 400.0, 0.2};

void run_identification(benchmark::State& state, Algorithm algorithm) {
  const BHCurve curve = synthetic_loop(kSteel, 5000.0, 1000);
  const BHObjective objective(curve);
  IdentifyOptions options;
  options.algorithm = algorithm;
  options.start = to_point(kSteel);
  options.seed = 1;
  std::int64_t evaluations = 0;
  for (auto _ : state) {
    const auto r = identify(objective, curve, options);
    evaluations = r.search.evaluations;
    benchmark::DoNotOptimize(r.fit.rmse);
  }
  state.counters["evaluations"] = static_cast<double>(evaluations);
}

void BM_IdentifyImprovedPso(benchmark::State& s) { run_identification(s, Algorithm::kImprovedPso); }
void BM_IdentifyPso(benchmark::State& s) { run_identification(s, Algorithm::kPso); }
#ifdef MRD_HAVE_PAGMO  // the reference peers, where pagmo2 was found
void BM_IdentifyPagmoPso(benchmark::State& s) { run_identification(s, Algorithm::kPagmoPso); }
void BM_IdentifyPagmoDe(benchmark::State& s) { run_identification(s, Algorithm::kPagmoDe); }
void BM_IdentifyPagmoSade(benchmark::State& s) { run_identification(s, Algorithm::kPagmoSade); }
void BM_IdentifyPagmoCmaes(benchmark::State& s) { run_identification(s, Algorithm::kPagmoCmaes); }
#endif

// One evaluation of Eq. 15 at the true parameters: 1,000 points plus the pre-cycle.
void BM_BHObjectiveEvaluation(benchmark::State& state) {
  const BHCurve curve = synthetic_loop(kSteel, 5000.0, 1000);
  const BHObjective objective(curve);
  std::vector<double> scratch(objective.points());
  const Point x = to_point(kSteel);
  for (auto _ : state) benchmark::DoNotOptimize(objective.evaluate(x, scratch).fitness);
}

BENCHMARK(BM_BHObjectiveEvaluation);
BENCHMARK(BM_IdentifyImprovedPso)->Unit(benchmark::kMillisecond)->UseRealTime();
BENCHMARK(BM_IdentifyPso)->Unit(benchmark::kMillisecond)->UseRealTime();
#ifdef MRD_HAVE_PAGMO
BENCHMARK(BM_IdentifyPagmoPso)->Unit(benchmark::kMillisecond)->UseRealTime();
BENCHMARK(BM_IdentifyPagmoDe)->Unit(benchmark::kMillisecond)->UseRealTime();
BENCHMARK(BM_IdentifyPagmoSade)->Unit(benchmark::kMillisecond)->UseRealTime();
BENCHMARK(BM_IdentifyPagmoCmaes)->Unit(benchmark::kMillisecond)->UseRealTime();
#endif

}  // namespace
