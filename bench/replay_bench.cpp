// mrd-bench-replay: how much faster than real time mrd-replay runs the control law over the
// measured runs in data/damper (docs/PERFORMANCE.md). The rate counter `x_real_time` is
// seconds of data replayed per second.
#include <benchmark/benchmark.h>

#include "config/config_loader.hpp"
#include "tools/replay/replay.hpp"
#include "record/run_reader.hpp"

namespace {

using namespace mrd::tools;

void replay_file(benchmark::State& state, const char* file, const char* columns, bool from_name) {
  mrd::record::RunReadOptions read;
  read.columns = mrd::record::parse_column_mapping(columns);
  read.current_from_name = from_name;
  const mrd::record::RecordedRun run = mrd::record::read_recorded_run(std::string(MRD_DATA_DIR) + "/" + file, read);
  ReplayOptions options;
  options.law = mrd::config::load_default_config().config.law;
  options.amps_per_volt = 0.5;
  for (auto _ : state) benchmark::DoNotOptimize(replay(run, options));
  state.SetItemsProcessed(state.iterations() * static_cast<std::int64_t>(run.size()));
  state.counters["x_real_time"] =
      benchmark::Counter(run.duration(), benchmark::Counter::kIsIterationInvariantRate);
}

void BM_ReplayDyke(benchmark::State& state) {
  replay_file(state, "damper/dyke-nees-prototype/ranran_50.csv",
              "t=time_s,D=displacement_cm,Y=voltage_V,F=force_N", false);
}
BENCHMARK(BM_ReplayDyke)->Unit(benchmark::kMillisecond);

// 200 Hz: each period lets the compensator's slew limit move 0.5 A, so its search integrates
// J-A over wide current spans; the costliest samples of the three.
void BM_ReplayQuiroz200Hz(benchmark::State& state) {
  replay_file(state, "damper/quiroz-utfsm/sine/25mm0x25Hz0x5A.txt",
              "1=time_s,2=displacement_mm,3=velocity_mm_s,4=force_N", true);
}
BENCHMARK(BM_ReplayQuiroz200Hz)->Unit(benchmark::kMillisecond);

void BM_ReplayQuiroz1kHz(benchmark::State& state) {
  replay_file(state, "damper/quiroz-utfsm/sine/5mm3Hz0x75A.txt",
              "1=time_s,2=displacement_mm,3=velocity_mm_s,4=force_N", true);
}
BENCHMARK(BM_ReplayQuiroz1kHz)->Unit(benchmark::kMillisecond);

}  // namespace
