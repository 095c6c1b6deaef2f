#include "firmware/probe.hpp"

#include <time.h>

#include <algorithm>
#include <chrono>
#include <cinttypes>
#include <cmath>

#include "common/cli/exit_code.hpp"
#include "firmware/hal_set.hpp"
#include "firmware/mock_drive.hpp"

namespace mrd::firmware {

ProbeExpectations ProbeExpectations::from(const config::ControllerConfig& config) {
  ProbeExpectations e;
  e.displacement_min = config.safety.displacement_min;
  e.displacement_max = config.safety.displacement_max;
  e.current_tolerance = config.safety.current_tolerance;
  switch (config.backends.driver) {
    case config::DeviceBackend::kMock: e.current_feedback = true; break;
    case config::DeviceBackend::kModbus: e.current_feedback = config.modbus.registers.has_current_feedback; break;
    case config::DeviceBackend::kCan: e.current_feedback = config.can.use_feedback; break;
  }
  return e;
}

void Probe::Range::add(double v) {
  min = count == 0 ? v : std::min(min, v);
  max = count == 0 ? v : std::max(max, v);
  ++count;
}

void Probe::disable_driver() { enable_failed_ = hal_.lines.set_enable(false) != hal::IoStatus::kOk; }

ProbeReading Probe::poll(hal::Timestamp now) {
  ProbeReading r{now, hal_.lvdt.latest(), hal_.driver.measured(), hal_.lines.driver_fault()};
  ++polls_;
  if (r.lvdt) {
    ++samples_;
    if (!r.lvdt->usable()) {
      ++unusable_;
    } else if (!std::isfinite(r.lvdt->value)) {
      ++not_finite_;
    } else {
      lvdt_.add(r.lvdt->value);
    }
  }
  if (r.current && std::isfinite(r.current->value)) current_.add(r.current->value);
  if (!r.fault) {
    ++fault_unreadable_;
  } else if (*r.fault) {
    ++fault_set_;
  }
  return r;
}

std::string Probe::problems() const {
  std::string out;
  char line[256];
  const auto add = [&out, &line] { out += line; out += '\n'; };
  if (enable_failed_) {
    std::snprintf(line, sizeof line, "the enable line could not be driven low");
    add();
  }
  if (samples_ == 0) {
    std::snprintf(line, sizeof line, "lvdt: no sample in %" PRIu64 " polls (check the bus, the address and the wiring)", polls_);
    add();
  } else if (lvdt_.count < expect_.min_samples) {
    std::snprintf(line, sizeof line,
                  "lvdt: %" PRIu64 " usable samples of %" PRIu64 " (%" PRIu64 " flagged invalid/corrupted/sensor fault, %" PRIu64
                  " not finite); at least %" PRIu64 " expected",
                  lvdt_.count, samples_, unusable_, not_finite_, expect_.min_samples);
    add();
  }
  if (lvdt_.count > 0 && (lvdt_.min < expect_.displacement_min || lvdt_.max > expect_.displacement_max)) {
    std::snprintf(line, sizeof line,
                  "lvdt: reads %.3f..%.3f mm, outside safety.displacement_min..max (%.3f..%.3f mm): check the "
                  "scale, offset, type and word order",
                  lvdt_.min * 1e3, lvdt_.max * 1e3, expect_.displacement_min * 1e3, expect_.displacement_max * 1e3);
    add();
  }
  if (expect_.current_feedback && current_.count == 0) {
    std::snprintf(line, sizeof line, "current: no reading, though the config says the driver reports one");
    add();
  }
  if (current_.count > 0 && std::max(std::fabs(current_.min), std::fabs(current_.max)) > expect_.current_tolerance) {
    std::snprintf(line, sizeof line,
                  "current: the driver reports %.3f..%.3f A with its enable low (more than safety.current_tolerance "
                  "%.3f A): check the feedback's scale, or the driver",
                  current_.min, current_.max, expect_.current_tolerance);
    add();
  }
  if (fault_unreadable_ > 0) {
    std::snprintf(line, sizeof line, "fault line: unreadable in %" PRIu64 " of %" PRIu64 " polls", fault_unreadable_, polls_);
    add();
  }
  if (fault_set_ > 0) {
    std::snprintf(line, sizeof line, "fault line: set in %" PRIu64 " of %" PRIu64 " polls (the supervisor would go SAFE)",
                  fault_set_, polls_);
    add();
  }
  return out;
}

std::string Probe::summary() const {
  char line[512];
  std::snprintf(line, sizeof line,
                "lvdt: %" PRIu64 " samples in %" PRIu64 " polls, %" PRIu64 " usable, range %.3f..%.3f mm\n"
                "current: %" PRIu64 " readings, range %.3f..%.3f A\n"
                "fault line: %" PRIu64 " clear, %" PRIu64 " set, %" PRIu64 " unreadable\n",
                samples_, polls_, lvdt_.count, lvdt_.min * 1e3, lvdt_.max * 1e3, current_.count, current_.min,
                current_.max, polls_ - fault_set_ - fault_unreadable_, fault_set_, fault_unreadable_);
  return line;
}

std::string Probe::format(const ProbeReading& r, hal::Timestamp start) {
  char line[256];
  int n = std::snprintf(line, sizeof line, "  t %6.3f s  lvdt ", std::chrono::duration<double>(r.time - start).count());
  const auto room = [&n] { return sizeof line - static_cast<std::size_t>(std::min<int>(n, sizeof line)); };
  if (r.lvdt) {
    n += std::snprintf(line + n, room(), "%9.4f mm (seq %" PRIu32 "%s)", r.lvdt->value * 1e3, r.lvdt->sequence,
                       r.lvdt->usable() ? "" : ", unusable");
  } else {
    n += std::snprintf(line + n, room(), "%9s   ", "none");
  }
  if (r.current) {
    n += std::snprintf(line + n, room(), "  current %7.4f A", r.current->value);
  } else {
    n += std::snprintf(line + n, room(), "  current    none");
  }
  std::snprintf(line + n, room(), "  fault %s\n", !r.fault ? "unreadable" : *r.fault ? "SET" : "clear");
  return line;
}

namespace {

void fail_each_line(const std::string& lines, std::FILE* out) {
  std::size_t from = 0;
  for (std::size_t end; (end = lines.find('\n', from)) != std::string::npos; from = end + 1) {
    std::fprintf(out, "probe: FAIL: %s\n", lines.substr(from, end - from).c_str());
  }
}

void sleep_until(hal::Timestamp t) {
  timespec ts{static_cast<time_t>(t.count() / 1'000'000'000), static_cast<long>(t.count() % 1'000'000'000)};
  while (clock_nanosleep(CLOCK_MONOTONIC, TIMER_ABSTIME, &ts, nullptr) != 0) {
  }
}

}  // namespace

int run_probe(const config::ControllerConfig& config, const ProbeOptions& options, std::FILE* out) {
  std::fprintf(out, "probe: lvdt=%s driver=%s lines=%s, the driver held off (enable low, no setpoint written)\n",
               to_string(config.backends.lvdt).data(), to_string(config.backends.driver).data(),
               to_string(config.backends.lines).data());
  const hal::MonotonicClock clock;
  HalSet hal(config, clock);
  if (const auto started = hal.start(); !started.ok) {
    std::fprintf(out, "%sprobe: FAIL: the back ends could not start (above)\n", started.error.c_str());
    return cli::kIo;
  }
  Probe probe(hal.devices(), ProbeExpectations::from(config));
  MockDrive mock(config, hal.mock());
  probe.disable_driver();

  const auto interval = std::chrono::duration_cast<hal::Timestamp>(std::chrono::duration<double>(options.interval_s));
  const auto polls = static_cast<int>(std::ceil(options.window_s / options.interval_s));
  const hal::Timestamp start = clock.now();
  for (int i = 1; i <= polls; ++i) {
    const hal::Timestamp at = start + i * interval;
    sleep_until(at);
    mock.advance(at);
    const ProbeReading r = probe.poll(at);
    if (i <= options.print_readings) std::fputs(Probe::format(r, start).c_str(), out);
  }
  const std::vector<std::string> links = hal.link_problems();
  const bool never_up = hal.link_never_up();
  hal.stop();
  std::fputs(probe.summary().c_str(), out);
  std::fputs(hal.counters().c_str(), out);
  // A link that never came up is the bus's fault, not the readings': say why, as mbpoll would,
  // and nothing of readings that could not come. A link lost on the way is one more problem.
  for (const std::string& link : links) std::fprintf(out, "probe: FAIL: %s\n", link.c_str());
  if (never_up) return cli::kIo;
  const std::string problems = probe.problems();
  if (problems.empty() && links.empty()) {
    std::fputs("probe: OK\n", out);
    return cli::kOk;
  }
  fail_each_line(problems, out);
  return cli::kBadInput;  // the readings are wrong
}

}  // namespace mrd::firmware
