#include "hal/gpio/gpiod_lines.hpp"

#include <poll.h>

#include <exception>
#include <string>

namespace mrd::hal::gpio {

namespace {

// The kernel's event queue holds 16 events; more in one cycle means the line is chattering
// and the newest event we read is still the line's latest level.
constexpr int kMaxEventsPerRead = 16;

std::bitset<32> flags_for(const GpioLineConfig& line) {
  return line.active_low ? gpiod::line_request::FLAG_ACTIVE_LOW : std::bitset<32>{};
}

}  // namespace

GpiodLines::~GpiodLines() {
  if (started_) (void)set_enable(false);
}

StartResult GpiodLines::start() {
  if (started_) return StartResult::failure("gpio: already started");
  if (const auto report = config_.validate(); !report.ok()) {
    return StartResult::failure("gpio config:\n" + report.to_string());
  }
  const std::string where = "gpio (" + config_.chip + ")";
  std::string step = "cannot open chip";
  try {
    chip_.open(config_.chip);
    const auto request_output = [&](const GpioLineConfig& line, const char* role, Output& out) {
      step = std::string("cannot request ") + role + " line " + std::to_string(line.offset);
      const gpiod::line l = chip_.get_line(static_cast<unsigned>(line.offset));
      l.request({config_.consumer(role), gpiod::line_request::DIRECTION_OUTPUT, flags_for(line)},
                0);
      out.bulk = gpiod::line_bulk({l});
    };
    request_output(config_.enable, "enable", enable_);
    request_output(config_.heartbeat, "heartbeat", heartbeat_);

    step = "cannot request fault line " + std::to_string(config_.fault.offset);
    fault_ = chip_.get_line(static_cast<unsigned>(config_.fault.offset));
    fault_.request({config_.consumer("fault"), gpiod::line_request::EVENT_BOTH_EDGES,
                    flags_for(config_.fault)});
    fault_fd_ = fault_.event_get_fd();
    fault_active_ = fault_.get_value() != 0;  // events from here on keep it current
  } catch (const std::exception& e) {
    release_all();
    return StartResult::failure(where + ": " + step + ": " + e.what());
  }
  started_ = true;
  return StartResult::success();
}

IoStatus GpiodLines::write(Output& out, bool active) noexcept {
  if (!started_) return IoStatus::kNotConnected;
  try {
    out.value[0] = active ? 1 : 0;
    out.bulk.set_values(out.value);
    return IoStatus::kOk;
  } catch (...) {
    (void)io_error();
    return IoStatus::kIoError;
  }
}

IoStatus GpiodLines::set_enable(bool enabled) { return write(enable_, enabled); }

IoStatus GpiodLines::write_heartbeat(bool high) { return write(heartbeat_, high); }

std::optional<bool> GpiodLines::driver_fault() {
  if (!started_) return std::nullopt;
  pollfd pfd{fault_fd_, POLLIN, 0};
  for (int i = 0; i < kMaxEventsPerRead; ++i) {
    const int ready = poll(&pfd, 1, 0);
    if (ready == 0) break;
    if (ready < 0 || (pfd.revents & POLLIN) == 0) return io_error();
    try {
      // Edge events carry the logical level (active-low applied) after the edge.
      fault_active_ = fault_.event_read().event_type == gpiod::line_event::RISING_EDGE;
    } catch (...) {
      return io_error();
    }
  }
  return fault_active_;
}

std::nullopt_t GpiodLines::io_error() noexcept {
  io_errors_.fetch_add(1, std::memory_order_relaxed);
  return std::nullopt;
}

void GpiodLines::release_all() noexcept {
  try {
    enable_.bulk = {};
    heartbeat_.bulk = {};
    fault_.reset();
    chip_.reset();
  } catch (...) {
  }
  fault_fd_ = -1;
}

}  // namespace mrd::hal::gpio
