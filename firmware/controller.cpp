#include "firmware/controller.hpp"

#include <chrono>
#include <cstdio>
#include <memory>
#include <optional>
#include <vector>

#include "common/cli/exit_code.hpp"
#include "firmware/config_reload.hpp"
#include "firmware/control_loop.hpp"
#include "firmware/hal_set.hpp"
#include "firmware/mock_drive.hpp"
#include "runtime/csv_telemetry_writer.hpp"
#include "runtime/journal.hpp"
#include "runtime/loop_report.hpp"
#include "runtime/rt_main.hpp"
#include "runtime/service_notifier.hpp"
#include "runtime/telemetry_alarm.hpp"
#include "runtime/supervisor_feed.hpp"

namespace mrd::firmware {

namespace {

// Runs on the main thread while the loop runs: every value it reads from the loop's side is an
// atomic (the statistics, the transition counts, the bus counters) or the feed's snapshot of
// the supervisor's state; nothing reads the ControlLoop itself.
void print_stats(std::FILE* out, const runtime::LoopStatistics& stats, const runtime::SupervisorFeed& feed,
                 const ControlLoop& loop, const HalSet& hal, bool histograms) {
  std::string text = "--- mrd-controller statistics ---\n" + runtime::format_loop_statistics(stats);
  if (histograms) {
    text += runtime::format_histogram("wake-up latency", stats.wake_latency);
    text += runtime::format_histogram("execution time", stats.execution);
  }
  text += "supervisor: " + std::string(to_string(feed.state())) + ", transitions:\n";
  text += runtime::format_transitions(loop.supervisor().transitions());
  text += hal.counters();
  std::fputs(text.c_str(), out);
  std::fflush(out);
}

// What telemetry lost so far (nothing without telemetry).
runtime::TelemetryLosses telemetry_losses(const runtime::TelemetryQueue* queue, const runtime::CsvTelemetryWriter* writer) {
  if (queue == nullptr || writer == nullptr) return {};
  return {.dropped = queue->dropped(), .lost = writer->lost(), .error = writer->last_error()};
}

runtime::ServiceStatus service_status(const config::ControllerConfig& config, const runtime::LoopStatistics& stats,
                                      const runtime::SupervisorFeed& feed, const runtime::TelemetryLosses& telemetry) {
  return {.state = feed.state(),
          .latched = feed.latched(),
          .rate = config.rate,
          .cycles = stats.cycles.get(),
          .overruns = stats.overruns.get(),
          .wake_p99_ns = stats.wake_latency.percentile(0.99),
          .telemetry = telemetry};
}

// The transitions the loop published since the last call, into the journal (main thread).
void log_transitions(runtime::SupervisorFeed& feed, const runtime::Journal& journal, hal::Timestamp start,
                     std::uint64_t& lost_logged, std::uint64_t& bounds_logged) {
  feed.drain([&](const runtime::SupervisorEvent& e) {
    journal.write(runtime::transition_priority(e), runtime::format_transition(e, start));
  });
  // A scale at its bound means the model's yield force is off by more than the correction may
  // take up: worth an engineer's look (identify the model again), not a fault.
  if (const std::uint64_t hits = feed.force_scale_bound_hits(); hits > bounds_logged) {
    char line[160];
    std::snprintf(line, sizeof line,
                  "force mode: the load-cell correction's yield force scale reached its bound (%.3f); "
                  "force.load_cell.max_correction limits it",
                  feed.force_scale_at_bound());
    journal.write(runtime::Priority::kWarning, line);
    bounds_logged = hits;
  }
  if (const std::uint64_t lost = feed.lost(); lost > lost_logged) {
    journal.write(runtime::Priority::kWarning,
                  "supervisor: " + std::to_string(lost - lost_logged) + " transitions not logged (the feed was full)");
    lost_logged = lost;
  }
}

// The run's verdict: kEndedSafe when a fault, not the stop, put the loop into the SAFE it ended
// in, or a bus link was down at the end (a run shorter than link_timeout never leaves INIT on a
// dead link), with the trigger and each bus whose link is down and why.
int report_ending(std::FILE* out, const runtime::Journal& journal, control::Trigger safe_cause,
                  const std::vector<std::string>& links) {
  for (const std::string& link : links) std::fprintf(out, "link down: %s\n", link.c_str());
  const bool through_fault = safe_cause != control::Trigger::kNone && safe_cause != control::Trigger::kShutdown;
  if (!through_fault && links.empty()) return cli::kOk;
  const std::string line = through_fault ? "the run ended in SAFE through " + std::string(control::to_string(safe_cause)) +
                                               ", not the stop (exit status 4)"
                                         : "the run ended with a bus link down (exit status 4)";
  std::fprintf(out, "%s\n", line.c_str());
  journal.write(runtime::Priority::kErr, line);
  return cli::kEndedSafe;
}

}  // namespace

int run_controller(const config::ControllerConfig& config, const RunOptions& options,
                   runtime::ProcessSignals& signals, std::FILE* out, const sigset_t* unblock) {
  const runtime::Journal journal = options.log != nullptr ? runtime::Journal(options.log, false, "mrd-controller")
                                                          : runtime::Journal::for_stderr("mrd-controller");
  runtime::RtSetupResult rt;
  runtime::lock_memory(config.realtime, rt);

  const hal::MonotonicClock clock;
  HalSet hal(config, clock);
  if (const auto started = hal.start(); !started.ok) {
    std::string error = "cannot start the back ends:\n" + started.error;
    while (error.ends_with('\n')) error.pop_back();
    journal.write(runtime::Priority::kErr, error);
    return cli::kIo;
  }
  const std::vector<hal::IoThread*> io_threads = hal.io_threads();

  std::unique_ptr<runtime::TelemetryQueue> queue;
  std::unique_ptr<runtime::CsvTelemetryWriter> writer;
  if (config.telemetry.enabled()) {
    queue = std::make_unique<runtime::TelemetryQueue>(static_cast<std::size_t>(config.telemetry.ring_size));
    writer = std::make_unique<runtime::CsvTelemetryWriter>(*queue, config.telemetry.flush_period,
                                                           config.law.mode == control::ControlMode::kForce);
    if (const auto started = writer->start(config.telemetry); !started.ok) {
      journal.write(runtime::Priority::kErr, started.error);
      return cli::kIo;
    }
  }

  ControlLoop loop(config.law, config.safety, hal.devices(), queue.get(), config.telemetry.decimation);
  MockDrive mock(config, hal.mock());
  runtime::SupervisorFeed feed;
  const auto cycle = [&](hal::Timestamp release) {
    mock.advance(release);
    feed.publish(loop.step(release));
  };

  const std::string mode = config.backends.demand
                               ? ", force mode, demand=" + std::string(to_string(*config.backends.demand)) +
                                     (config.backends.load_cell
                                          ? ", load_cell=" + std::string(to_string(*config.backends.load_cell))
                                          : std::string())
                               : std::string();
  std::fprintf(out, "mrd-controller: %.0f Hz, lvdt=%s driver=%s lines=%s%s%s%s\n", config.rate,
               to_string(config.backends.lvdt).data(), to_string(config.backends.driver).data(),
               to_string(config.backends.lines).data(), mode.c_str(), mock.moves_lvdt() ? ", mock LVDT on the simulation sine" : "",
               writer ? (", telemetry " + writer->path()).c_str() : "");

  runtime::LoopStatistics stats;
  runtime::ServiceNotifier notifier;
  const hal::Timestamp start = clock.now();
  std::uint64_t lost_logged = 0;
  std::uint64_t bounds_logged = 0;
  runtime::TelemetryAlarm telemetry_alarm;
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
      // The buses are up and the loop thread is set up: systemd may consider the service started.
      .ready =
          [&](const runtime::RtSetupResult& done) {
            std::fprintf(out, "%s\n", runtime::describe_rt_setup(config.realtime, done, io_threads.size()).c_str());
            std::fflush(out);
            for (const auto& w : done.warnings) journal.write(runtime::Priority::kWarning, "warning: " + w);
            notifier.ready(service_status(config, stats, feed, {}), clock.now());
          },
      .print_stats = [&] { print_stats(out, stats, feed, loop, hal, options.bench); },
      .clear_latch =
          [&] {
            loop.request_clear_latch();
            journal.write(runtime::Priority::kNotice, "SIGUSR2: an operator cleared the latch");
          },
      // Never a stop: the file checked again, the running config kept (ConfigReload).
      .reload =
          [&] {
            const auto outcome = (options.reload != nullptr ? *options.reload : ConfigReload("", "")).check();
            journal.write(outcome.priority, outcome.text);
          },
      .tick =
          [&](hal::Timestamp now) {
            log_transitions(feed, journal, start, lost_logged, bounds_logged);
            const auto losses = telemetry_losses(queue.get(), writer.get());
            if (const auto line = telemetry_alarm.check(losses, now)) journal.write(line->priority, line->text);
            runtime::ServiceStatus status = service_status(config, stats, feed, losses);
            status.bus_stalled = loop.bus_stalled();
            notifier.tick(now, status);
          }};
  runtime::run_real_time(run, signals, unblock, rt, stats, cycle, hooks);
  // The loop thread has ended (joined): the final cycle's transition is in the feed.
  log_transitions(feed, journal, start, lost_logged, bounds_logged);
  const int stop_signal = signals.stop_signal.load();
  const std::string why = stop_signal != 0  ? std::string("stopped on ") + runtime::signal_name(stop_signal)
                          : signals.stop.load() ? std::string("stopped on request")
                                                : std::string("stopped after the run's duration");
  journal.write(runtime::Priority::kNotice, why + ", fail-safe current written");
  notifier.stopping(why);
  if (writer) writer->stop();
  const std::vector<std::string> links = hal.link_problems();  // before stop(), which takes every link down
  hal.stop();

  print_stats(out, stats, feed, loop, hal, options.bench);
  std::fprintf(out, "final setpoint %.3f A (fail-safe %.3f A), enable %s\n", loop.last().setpoint,
               config.safety.fail_safe_current, loop.last().enable ? "on" : "off");
  const int status = report_ending(out, journal, feed.safe_cause(), links);
  if (!queue) return status;
  // A run whose file is incomplete exits with the I/O code: its record cannot be trusted whole.
  const bool failed = writer->failures() > 0;
  std::fprintf(out, "telemetry: %llu records offered, %llu written, %llu dropped, %llu over the size cap, %llu lost to I/O -> %s\n",
               static_cast<unsigned long long>(queue->offered()), static_cast<unsigned long long>(writer->written()),
               static_cast<unsigned long long>(queue->dropped()), static_cast<unsigned long long>(writer->capped()),
               static_cast<unsigned long long>(writer->lost()), writer->path().c_str());
  if (failed) {
    const std::string error = "telemetry: FAILED, " + std::to_string(writer->failures()) + " write(s) failed (last: " +
                              runtime::telemetry_error_text(writer->last_error()) + "); " + writer->path() + " is incomplete";
    std::fprintf(out, "%s\n", error.c_str());
    journal.write(runtime::Priority::kErr, error);
  }
  if (const auto t0 = writer->start_time()) {
    std::fprintf(out, "telemetry: time_s 0 is CLOCK_MONOTONIC %.9f s\n", std::chrono::duration<double>(*t0).count());
  }
  return failed ? cli::kIo : status;
}

}  // namespace mrd::firmware
