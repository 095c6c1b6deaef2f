#include "firmware/controller.hpp"

#include <chrono>
#include <memory>
#include <optional>
#include <vector>

#include "firmware/control_loop.hpp"
#include "runtime/csv_telemetry_writer.hpp"
#include "firmware/hal_set.hpp"
#include "hal/mock/mock_motion.hpp"
#include "runtime/loop_report.hpp"
#include "runtime/rt_main.hpp"

namespace mrd::firmware {

namespace {

void print_stats(std::FILE* out, const runtime::LoopStatistics& stats, const ControlLoop& loop,
                 const HalSet& hal, bool histograms) {
  std::string text = "--- mrd-controller statistics ---\n" + runtime::format_loop_statistics(stats);
  if (histograms) {
    text += runtime::format_histogram("wake-up latency", stats.wake_latency);
    text += runtime::format_histogram("execution time", stats.execution);
  }
  text += "supervisor: " + std::string(to_string(loop.state())) + ", transitions:\n";
  text += runtime::format_transitions(loop.supervisor().transitions());
  text += hal.counters();
  std::fputs(text.c_str(), out);
  std::fflush(out);
}

}  // namespace

int run_controller(const config::ControllerConfig& config, const RunOptions& options,
                   runtime::ProcessSignals& signals, std::FILE* out, const sigset_t* unblock) {
  runtime::RtSetupResult rt;
  runtime::lock_memory(config.realtime, rt);

  const hal::MonotonicClock clock;
  HalSet hal(config, clock);
  if (const auto started = hal.start(); !started.ok) {
    std::fprintf(stderr, "mrd-controller: cannot start the back ends:\n%s", started.error.c_str());
    return 1;
  }
  const std::vector<hal::IoThread*> io_threads = hal.io_threads();

  std::unique_ptr<runtime::TelemetryQueue> queue;
  std::unique_ptr<runtime::CsvTelemetryWriter> writer;
  if (config.telemetry.enabled()) {
    queue = std::make_unique<runtime::TelemetryQueue>(static_cast<std::size_t>(config.telemetry.ring_size));
    writer = std::make_unique<runtime::CsvTelemetryWriter>(*queue, config.telemetry.flush_period);
    if (const auto started = writer->start(config.telemetry); !started.ok) {
      std::fprintf(stderr, "mrd-controller: %s\n", started.error.c_str());
      return 1;
    }
  }

  ControlLoop loop(config.law, config.safety, hal.devices(), queue.get(), config.telemetry.decimation);
  hal::mock::MockHal* mock = hal.mock();
  std::optional<hal::mock::MockMotion> motion;
  if (config.backends.lvdt == config::DeviceBackend::kMock) {
    const auto& s = config.simulation;
    motion.emplace(s.amplitude, s.frequency, s.lvdt_noise, s.seed);
  }

  const auto cycle = [&](hal::Timestamp release) {
    if (motion) {
      motion->advance(*mock, release);
    } else if (mock != nullptr) {
      mock->clock.set(release);
    }
    loop.step(release);
  };

  std::fprintf(out, "mrd-controller: %.0f Hz, lvdt=%s driver=%s lines=%s%s%s\n", config.rate,
               to_string(config.backends.lvdt).data(), to_string(config.backends.driver).data(),
               to_string(config.backends.lines).data(), motion ? ", mock LVDT on the simulation sine" : "",
               writer ? (", telemetry " + writer->path()).c_str() : "");

  runtime::LoopStatistics stats;
  const runtime::RealTimeRun run{.realtime = config.realtime,
                                 .period = config.period(),
                                 .max_cycles = static_cast<std::uint64_t>(options.duration_s * config.rate + 0.5),
                                 .io_threads = io_threads};
  const runtime::RealTimeHooks hooks{
      // One more cycle, in SAFE, so the driver holds the fail-safe current before exit.
      .finish =
          [&](hal::Timestamp next) {
            loop.request_shutdown();
            cycle(std::max(next, clock.now()));
          },
      .ready =
          [&](const runtime::RtSetupResult& done) {
            std::fprintf(out, "%s\n", runtime::describe_rt_setup(config.realtime, done, io_threads.size()).c_str());
            for (const auto& w : done.warnings) std::fprintf(stderr, "mrd-controller: warning: %s\n", w.c_str());
            std::fflush(out);
          },
      .print_stats = [&] { print_stats(out, stats, loop, hal, options.bench); }};
  runtime::run_real_time(run, signals, unblock, rt, stats, cycle, hooks);
  if (writer) writer->stop();
  hal.stop();

  print_stats(out, stats, loop, hal, options.bench);
  std::fprintf(out, "final setpoint %.3f A (fail-safe %.3f A), enable %s\n", loop.last().setpoint,
               config.safety.fail_safe_current, loop.last().enable ? "on" : "off");
  if (queue) {
    std::fprintf(out, "telemetry: %llu records offered, %llu written, %llu dropped, %llu over the size cap -> %s\n",
                 static_cast<unsigned long long>(queue->offered()),
                 static_cast<unsigned long long>(writer->written()),
                 static_cast<unsigned long long>(queue->dropped()),
                 static_cast<unsigned long long>(writer->capped()), writer->path().c_str());
    if (const auto t0 = writer->start_time()) {
      std::fprintf(out, "telemetry: time_s 0 is CLOCK_MONOTONIC %.9f s\n",
                   std::chrono::duration<double>(*t0).count());
    }
  }
  return 0;
}

}  // namespace mrd::firmware
