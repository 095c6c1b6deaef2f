#include "tests/firmware/soak.hpp"

#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <random>

#include "config/config_loader.hpp"
#include "firmware/control_loop.hpp"
#include "telemetry/csv_telemetry_writer.hpp"
#include "telemetry/telemetry_queue.hpp"
#include "hal/mock/mock_hal.hpp"
#include "sim/damper_plant.hpp"
#include "sim/displacement_profile.hpp"

namespace mrd::test {

namespace {

using control::SupervisorState;
using hal::mock::FaultKind;

long resident_kib() {
  long pages_total = 0;
  long pages_resident = 0;
  std::FILE* f = std::fopen("/proc/self/statm", "r");
  if (f == nullptr) return -1;
  const int n = std::fscanf(f, "%ld %ld", &pages_total, &pages_resident);
  std::fclose(f);
  return n == 2 ? pages_resident * (sysconf(_SC_PAGESIZE) / 1024) : -1;
}

// One fault after another: a random kind for 1 to 3000 periods, then 0 to 4000 clean periods.
// The script holds only the current fault, so the mock's lookups stay short over 1e7 cycles.
class RandomFaults {
 public:
  RandomFaults(std::uint32_t seed, hal::Timestamp period) : rng_(seed), period_(period) {}

  // Called before each cycle; replaces the script when the current fault and its gap are over.
  void update(hal::mock::MockHal& hal, std::int64_t cycle, SoakFigures& figures) {
    if (cycle < next_start_) return;
    // The LVDT's and the driver's faults: the soak runs table4 mode, which reads no demand.
    std::uniform_int_distribution<int> kind(0, static_cast<int>(FaultKind::kDemandMissing) - 1);
    std::uniform_int_distribution<std::int64_t> length(1, 3000);
    std::uniform_int_distribution<std::int64_t> gap(0, 4000);
    const auto k = static_cast<FaultKind>(kind(rng_));
    const std::int64_t end = cycle + length(rng_);
    double parameter = 0.0;
    if (k == FaultKind::kOutOfRange) parameter = 0.2;        // [m], outside +-50 mm
    if (k == FaultKind::kDroppedSample) parameter = 1 + static_cast<double>(rng_() % 4);
    if (k == FaultKind::kCurrentBias) parameter = 0.5;       // [A], over the 0.1 A tolerance
    if (k == FaultKind::kDisplacementJump) parameter = 0.01;  // [m] back and forth
    if (k == FaultKind::kFutureTimestamp) parameter = 0.2;   // [s] ahead
    hal.script = hal::mock::FaultScript{
        {k, hal::mock::cycle_time(cycle, period_), hal::mock::cycle_time(end, period_), parameter}};
    fault_end_ = end;
    next_start_ = end + gap(rng_);
    ++figures.faults;
  }
  // The first cycle with no fault active after the last one.
  [[nodiscard]] std::int64_t clean_since() const { return fault_end_; }

 private:
  std::mt19937 rng_;
  hal::Timestamp period_;
  std::int64_t next_start_ = 0;
  std::int64_t fault_end_ = 0;
};

// The rig of the soak: the config's sine through the simulated damper (the same physics as the
// observer's), its LVDT reading handed to the mock HAL.
class SineRig {
 public:
  SineRig(const config::SimulationConfig& s, const model::DamperModel& truth, double period, hal::mock::MockHal& hal)
      : profile_{s.amplitude, s.frequency},
        plant_(truth, sim::PlantSettings{.sample_period = period, .lvdt_noise_rms = s.lvdt_noise, .seed = s.seed}),
        hal_(hal) {}

  void advance(hal::Timestamp now) {
    hal_.clock.set(now);
    const double t = std::chrono::duration<double>(now).count();
    last_ = plant_.step({.displacement = profile_.displacement(t), .velocity = profile_.velocity(t), .coil_current = hal_.driver.last_setpoint()});
    hal_.lvdt.set_value(last_.lvdt_displacement);
  }
  [[nodiscard]] const sim::PlantReading& last() const { return last_; }

 private:
  sim::SineProfile profile_;
  sim::DamperPlant plant_;
  hal::mock::MockHal& hal_;
  sim::PlantReading last_;
};

}  // namespace

SoakFigures run_soak(std::uint64_t cycles, std::uint32_t seed) {
  auto config = config::load_default_config().config;
  // The default leaves the frozen check off; the simulated rig never rests, so a frozen-value
  // fault trips it here like any other bad sample.
  config.safety.frozen_periods = 50;
  const hal::Timestamp period = config.period();
  const auto& safety = config.safety;
  // The supervisor may need a few periods past recovery_periods: the first fresh sample after
  // a stale spell, a dropped sample's gap flag.
  const std::int64_t recovery_limit = safety.recovery_periods + safety.stale_periods + 5;

  hal::mock::MockHal hal;
  telemetry::TelemetryQueue queue(static_cast<std::size_t>(config.telemetry.ring_size));
  telemetry::CsvTelemetryWriter writer(queue, config.telemetry.flush_period);
  if (!writer.start("/dev/null").ok) return {};
  firmware::ControlLoop loop(config.law, safety,
                             firmware::HalDevices{hal.lvdt, hal.driver, hal.lines}, &queue);
  SineRig rig(config.simulation, config.law.damper, 1.0 / config.rate, hal);
  RandomFaults faults(seed, period);

  SoakFigures f;
  f.Ms = config.law.damper.jiles_atherton.Ms;
  const auto warmup = static_cast<std::int64_t>(cycles / 20);
  const auto sample_every = std::max<std::int64_t>(1, static_cast<std::int64_t>(cycles / 100));
  const auto t0 = std::chrono::steady_clock::now();
  for (std::int64_t c = 0; c < static_cast<std::int64_t>(cycles); ++c) {
    faults.update(hal, c, f);
    const hal::Timestamp now = hal::mock::cycle_time(c, period);
    rig.advance(now);
    const auto& record = loop.step(now);

    const double M = loop.law().observer().magnetics().M();
    if (!std::isfinite(M) || !std::isfinite(record.B) || !std::isfinite(record.force) ||
        !std::isfinite(rig.last().B)) {
      ++f.non_finite;
    }
    f.max_abs_M_observer = std::max(f.max_abs_M_observer, std::fabs(M));
    f.max_abs_B_observer = std::max(f.max_abs_B_observer, std::fabs(record.B));
    f.max_abs_B_plant = std::max(f.max_abs_B_plant, std::fabs(rig.last().B));

    // The operator: a latched SAFE is looked at and cleared once the fault has gone, so the
    // recovery is judged from there like any other.
    if (loop.supervisor().latched() && c >= faults.clean_since()) {
      ++f.latches;
      loop.request_clear_latch();
    }
    const bool holding = loop.state() == SupervisorState::kSafe || loop.state() == SupervisorState::kInit;
    if (holding && c >= faults.clean_since()) {
      const auto clean = static_cast<std::uint64_t>(c - faults.clean_since() + 1);
      f.longest_recovery = std::max(f.longest_recovery, clean);
      if (static_cast<std::int64_t>(clean) > recovery_limit) ++f.stuck_in_safe;
    }
    if (c == warmup) f.rss_after_warmup_kib = resident_kib();
    if (c > warmup && c % sample_every == 0) f.rss_max_kib = std::max(f.rss_max_kib, resident_kib());
  }
  writer.stop();
  f.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  f.rss_max_kib = std::max(f.rss_max_kib, resident_kib());
  f.cycles = loop.cycles();
  const auto& transitions = loop.supervisor().transitions();
  f.safe_entries = transitions.into(SupervisorState::kSafe);
  f.recoveries = transitions.get(SupervisorState::kSafe, SupervisorState::kRun,
                                 control::Trigger::kGoodPeriods);
  f.telemetry_offered = queue.offered();
  f.telemetry_written = writer.written();
  f.telemetry_dropped = queue.dropped();
  return f;
}

}  // namespace mrd::test
