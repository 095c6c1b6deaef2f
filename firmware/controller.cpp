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
#include "telemetry/csv_telemetry_writer.hpp"
#include "telemetry/journal.hpp"
#include "runtime/loop_report.hpp"
#include "runtime/rt_main.hpp"
#include "telemetry/service_notifier.hpp"
#include "telemetry/telemetry_alarm.hpp"
#include "telemetry/supervisor_feed.hpp"

namespace mrd::firmware {

namespace {

// What telemetry lost so far (nothing without telemetry).
telemetry::TelemetryLosses telemetry_losses(const telemetry::TelemetryQueue* queue, const telemetry::CsvTelemetryWriter* writer) {
  if (queue == nullptr || writer == nullptr) return {};
  return {.dropped = queue->dropped(), .lost = writer->lost(), .error = writer->last_error()};
}

telemetry::ServiceStatus service_status(const config::ControllerConfig& config, const runtime::LoopStatistics& stats,
                                      const telemetry::SupervisorFeed& feed, const telemetry::TelemetryLosses& telemetry) {
  return {.state = feed.state(),
          .latched = feed.latched(),
          .rate = config.rate,
          .cycles = stats.cycles.get(),
          .overruns = stats.overruns.get(),
          .wake_p99_ns = stats.wake_latency.percentile(0.99),
          .telemetry = telemetry};
}

// The run's verdict: kEndedSafe when a fault, not the stop, put the loop into the SAFE it ended
// in, or a bus link was down at the end (a run shorter than link_timeout never leaves INIT on a
// dead link), with the trigger and each bus whose link is down and why.
int report_ending(std::FILE* out, const telemetry::Journal& journal, control::Trigger safe_cause,
                  const std::vector<std::string>& links) {
  for (const std::string& link : links) std::fprintf(out, "link down: %s\n", link.c_str());
  const bool through_fault = safe_cause != control::Trigger::kNone && safe_cause != control::Trigger::kShutdown;
  if (!through_fault && links.empty()) return cli::kOk;
  const std::string line = through_fault ? "the run ended in SAFE through " + std::string(control::to_string(safe_cause)) +
                                               ", not the stop (exit status 4)"
                                         : "the run ended with a bus link down (exit status 4)";
  std::fprintf(out, "%s\n", line.c_str());
  journal.write(telemetry::Priority::kErr, line);
  return cli::kEndedSafe;
}

std::string stop_reason(const runtime::ProcessSignals& signals) {
  const int stop_signal = signals.stop_signal.load();
  return stop_signal != 0      ? std::string("stopped on ") + runtime::signal_name(stop_signal)
         : signals.stop.load() ? std::string("stopped on request")
                               : std::string("stopped after the run's duration");
}

// mrd-controller's run: a method per step of its lifecycle, which run_controller calls in order,
// and one per hook of the real-time skeleton. configure() builds the members after
// lock_memory(); they are torn down in the reverse of their order here.
class Controller final : public runtime::RealTimeHooks {
 public:
  Controller(const config::ControllerConfig& config, const RunOptions& options, std::FILE* out)
      : config_(config),
        options_(options),
        out_(out),
        journal_(options.log != nullptr ? telemetry::Journal(options.log, false, "mrd-controller")
                                        : telemetry::Journal::for_stderr("mrd-controller")) {}

  [[nodiscard]] int configure();
  void activate();
  void run(runtime::ProcessSignals& signals, const sigset_t* unblock);
  void deactivate(const runtime::ProcessSignals& signals);
  [[nodiscard]] int report();

 private:
  [[nodiscard]] bool start_telemetry();
  void cycle(hal::Timestamp release) {
    mock_->advance(release);
    feed_.publish(loop_->step(release));
  }
  void finish(hal::Timestamp next_release) override;
  void ready(const runtime::RtSetupResult& done) override;
  void print_stats() override;
  void clear_latch() override;
  bool reload() override;
  void tick(hal::Timestamp now) override;
  void log_transitions();
  [[nodiscard]] bool report_telemetry();

  const config::ControllerConfig& config_;
  const RunOptions& options_;
  std::FILE* out_;
  const telemetry::Journal journal_;
  runtime::RtSetupResult rt_;
  const hal::MonotonicClock clock_;
  std::optional<HalSet> hal_;
  std::unique_ptr<telemetry::TelemetryQueue> queue_;
  std::unique_ptr<telemetry::CsvTelemetryWriter> writer_;
  std::optional<ControlLoop> loop_;
  std::optional<MockDrive> mock_;
  telemetry::SupervisorFeed feed_;
  runtime::LoopStatistics stats_;
  telemetry::ServiceNotifier notifier_;
  telemetry::TelemetryAlarm telemetry_alarm_;
  hal::Timestamp start_{};
  std::uint64_t lost_logged_ = 0;
  std::uint64_t bounds_logged_ = 0;
  std::vector<std::string> links_down_;  // as they were before the buses stopped
};

// The back ends started, the telemetry writer running, the loop built: kOk, or kIo.
int Controller::configure() {
  runtime::lock_memory(config_.realtime, rt_);
  hal_.emplace(config_, clock_);
  if (const auto started = hal_->start(); !started.ok) {
    std::string error = "cannot start the back ends:\n" + started.error;
    while (error.ends_with('\n')) error.pop_back();
    journal_.write(telemetry::Priority::kErr, error);
    return cli::kIo;
  }
  if (config_.telemetry.enabled() && !start_telemetry()) return cli::kIo;
  loop_.emplace(config_.law, config_.safety, hal_->devices(), queue_.get(), config_.telemetry.decimation);
  mock_.emplace(config_, hal_->mock());
  return cli::kOk;
}

bool Controller::start_telemetry() {
  queue_ = std::make_unique<telemetry::TelemetryQueue>(static_cast<std::size_t>(config_.telemetry.ring_size));
  writer_ = std::make_unique<telemetry::CsvTelemetryWriter>(*queue_, config_.telemetry.flush_period,
                                                          config_.law.mode == control::ControlMode::kForce);
  if (const auto started = writer_->start(config_.telemetry); !started.ok) {
    journal_.write(telemetry::Priority::kErr, started.error);
    return false;
  }
  return true;
}

// What runs, on one line; the run's time starts here.
void Controller::activate() {
  const auto& backends = config_.backends;
  const std::string mode =
      backends.demand ? ", force mode, demand=" + std::string(to_string(*backends.demand)) +
                            (backends.load_cell ? ", load_cell=" + std::string(to_string(*backends.load_cell)) : std::string())
                      : std::string();
  std::fprintf(out_, "mrd-controller: %.0f Hz, lvdt=%s driver=%s lines=%s%s%s%s\n", config_.rate,
               to_string(backends.lvdt).data(), to_string(backends.driver).data(), to_string(backends.lines).data(),
               mode.c_str(), mock_->moves_lvdt() ? ", mock LVDT on the simulation sine" : "",
               writer_ ? (", telemetry " + writer_->path()).c_str() : "");
  start_ = clock_.now();
}

// The loop on its real-time thread until the duration ends or a stop signal, then its final cycle.
void Controller::run(runtime::ProcessSignals& signals, const sigset_t* unblock) {
  const runtime::RealTimeRun run{.realtime = config_.realtime,
                                 .period = config_.period(),
                                 .max_cycles = static_cast<std::uint64_t>(options_.duration_s * config_.rate + 0.5),
                                 .io_threads = hal_->io_threads()};
  runtime::run_real_time(run, signals, unblock, rt_, stats_, [this](hal::Timestamp release) { cycle(release); },
                         *this);
}

// After the final cycle wrote the fail-safe current: the stop logged, the writer and the buses down.
void Controller::deactivate(const runtime::ProcessSignals& signals) {
  // The loop thread has ended (joined): the final cycle's transition is in the feed.
  log_transitions();
  const std::string why = stop_reason(signals);
  journal_.write(telemetry::Priority::kNotice, why + ", fail-safe current written");
  notifier_.stopping(why);
  if (writer_) writer_->stop();
  links_down_ = hal_->link_problems();  // before stop(), which takes every link down
  hal_->stop();
}

// The run's account on `out`; the exit code.
int Controller::report() {
  print_stats();
  std::fprintf(out_, "final setpoint %.3f A (fail-safe %.3f A), enable %s\n", loop_->last().setpoint,
               config_.safety.fail_safe_current, loop_->last().enable ? "on" : "off");
  const int status = report_ending(out_, journal_, feed_.safe_cause(), links_down_);
  if (!queue_) return status;
  // A run whose file is incomplete exits with the I/O code: its record cannot be trusted whole.
  return report_telemetry() ? status : cli::kIo;
}

// False when a write failed.
bool Controller::report_telemetry() {
  std::fprintf(out_, "telemetry: %llu records offered, %llu written, %llu dropped, %llu over the size cap, %llu lost to I/O -> %s\n",
               static_cast<unsigned long long>(queue_->offered()), static_cast<unsigned long long>(writer_->written()),
               static_cast<unsigned long long>(queue_->dropped()), static_cast<unsigned long long>(writer_->capped()),
               static_cast<unsigned long long>(writer_->lost()), writer_->path().c_str());
  const bool failed = writer_->failures() > 0;
  if (failed) {
    const std::string error = "telemetry: FAILED, " + std::to_string(writer_->failures()) + " write(s) failed (last: " +
                              telemetry::telemetry_error_text(writer_->last_error()) + "); " + writer_->path() + " is incomplete";
    std::fprintf(out_, "%s\n", error.c_str());
    journal_.write(telemetry::Priority::kErr, error);
  }
  if (const auto t0 = writer_->start_time()) {
    std::fprintf(out_, "telemetry: time_s 0 is CLOCK_MONOTONIC %.9f s\n", std::chrono::duration<double>(*t0).count());
  }
  return !failed;
}

// One more cycle, in SAFE, so the driver holds the fail-safe current before exit.
void Controller::finish(hal::Timestamp next_release) {
  loop_->request_shutdown();
  cycle(std::max(next_release, clock_.now()));
}

// The buses are up and the loop thread is set up: systemd may consider the service started.
void Controller::ready(const runtime::RtSetupResult& done) {
  std::fprintf(out_, "%s\n", runtime::describe_rt_setup(config_.realtime, done, hal_->io_threads().size()).c_str());
  std::fflush(out_);
  for (const auto& w : done.warnings) journal_.write(telemetry::Priority::kWarning, "warning: " + w);
  notifier_.ready(service_status(config_, stats_, feed_, {}), clock_.now());
}

// On SIGUSR1 the main thread runs this while the loop runs: every value it reads from the
// loop's side is an atomic (the statistics, the transition counts, the bus counters) or the
// feed's snapshot of the supervisor's state; nothing reads the ControlLoop itself.
void Controller::print_stats() {
  std::string text = "--- mrd-controller statistics ---\n" + runtime::format_loop_statistics(stats_);
  if (options_.bench) {
    text += runtime::format_histogram("wake-up latency", stats_.wake_latency);
    text += runtime::format_histogram("execution time", stats_.execution);
  }
  text += "supervisor: " + std::string(to_string(feed_.state())) + ", transitions:\n";
  text += telemetry::format_transitions(loop_->supervisor().transitions());
  text += hal_->counters();
  std::fputs(text.c_str(), out_);
  std::fflush(out_);
}

void Controller::clear_latch() {
  loop_->request_clear_latch();
  journal_.write(telemetry::Priority::kNotice, "SIGUSR2: an operator cleared the latch");
}

// Never a stop: the file checked again, the running config kept (ConfigReload).
bool Controller::reload() {
  const auto outcome = (options_.reload != nullptr ? *options_.reload : ConfigReload("", "")).check();
  journal_.write(outcome.priority, outcome.text);
  return true;
}

void Controller::tick(hal::Timestamp now) {
  log_transitions();
  const auto losses = telemetry_losses(queue_.get(), writer_.get());
  if (const auto line = telemetry_alarm_.check(losses, now)) journal_.write(line->priority, line->text);
  telemetry::ServiceStatus status = service_status(config_, stats_, feed_, losses);
  status.bus_stalled = loop_->bus_stalled();
  notifier_.tick(now, status);
}

// The transitions the loop published since the last call, into the journal (main thread).
void Controller::log_transitions() {
  feed_.drain([&](const telemetry::SupervisorEvent& e) {
    journal_.write(telemetry::transition_priority(e), telemetry::format_transition(e, start_));
  });
  // A scale at its bound means the model's yield force is off by more than the correction may
  // take up: worth an engineer's look (identify the model again), not a fault.
  if (const std::uint64_t hits = feed_.force_scale_bound_hits(); hits > bounds_logged_) {
    char line[160];
    std::snprintf(line, sizeof line,
                  "force mode: the load-cell correction's yield force scale reached its bound (%.3f); "
                  "force.load_cell.max_correction limits it",
                  feed_.force_scale_at_bound());
    journal_.write(telemetry::Priority::kWarning, line);
    bounds_logged_ = hits;
  }
  if (const std::uint64_t lost = feed_.lost(); lost > lost_logged_) {
    journal_.write(telemetry::Priority::kWarning,
                   "supervisor: " + std::to_string(lost - lost_logged_) + " transitions not logged (the feed was full)");
    lost_logged_ = lost;
  }
}

}  // namespace

int run_controller(const config::ControllerConfig& config, const RunOptions& options,
                   runtime::ProcessSignals& signals, std::FILE* out, const sigset_t* unblock) {
  Controller controller(config, options, out);
  if (const int status = controller.configure(); status != cli::kOk) return status;
  controller.activate();
  controller.run(signals, unblock);
  controller.deactivate(signals);
  return controller.report();
}

}  // namespace mrd::firmware
