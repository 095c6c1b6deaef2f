// Screening's cost per sample (docs/PERFORMANCE.md; the goal: under 1 s per million samples),
// on Dyke's measured run (74,068 samples at 3 kHz, velocity recorded).
#include <benchmark/benchmark.h>

#include "record/run_columns.hpp"
#include "record/run_reader.hpp"
#include "tools/residual/screening.hpp"

namespace {

void BM_ScreenDyke(benchmark::State& state) {
  mrd::record::RunReadOptions o;
  o.columns = mrd::record::parse_column_mapping("t=time_s,D=displacement_cm,Y=voltage_V,F=force_N,V=velocity_cm_s");
  const auto run = mrd::record::read_recorded_run(MRD_DATA_DIR "/damper/dyke-nees-prototype/ranran_50.csv", o);
  for (auto _ : state) benchmark::DoNotOptimize(mrd::tools::screen_run(run).excluded_samples);
  state.SetItemsProcessed(state.iterations() * static_cast<std::int64_t>(run.size()));
}
BENCHMARK(BM_ScreenDyke)->Unit(benchmark::kMillisecond);

}  // namespace
