#include "hal/modbus/modbus_backend.hpp"

#include <modbus/modbus.h>
#include <pthread.h>

#include <algorithm>
#include <array>
#include <cerrno>
#include <string>

namespace mrd::hal::modbus {

namespace {

using std::chrono::steady_clock;

void split(std::chrono::microseconds t, std::uint32_t& sec, std::uint32_t& usec) {
  sec = static_cast<std::uint32_t>(t.count() / 1'000'000);
  usec = static_cast<std::uint32_t>(t.count() % 1'000'000);
}

bool is_exception_response(int err) { return err >= EMBXILFUN && err <= EMBXGTAR; }

void bump(std::atomic<std::uint64_t>& c) { c.fetch_add(1, std::memory_order_relaxed); }

std::string modbus_error(const char* what) {
  return std::string(what) + ": " + modbus_strerror(errno);
}

}  // namespace

ModbusBackend::ModbusBackend(ModbusConfig config, const Clock& clock)
    : config_(std::move(config)), clock_(clock) {}

ModbusBackend::~ModbusBackend() {
  stop();
  if (ctx_ != nullptr) modbus_free(ctx_);
}

StartResult ModbusBackend::start() {
  if (thread_.joinable()) return StartResult::failure("modbus: already started");
  if (const auto report = config_.validate(); !report.ok()) {
    return StartResult::failure("modbus config:\n" + report.to_string());
  }
  if (ctx_ == nullptr) {
    if (config_.transport == Transport::kTcp) {
      const std::string service = std::to_string(config_.tcp.port);
      ctx_ = modbus_new_tcp_pi(config_.tcp.host.c_str(), service.c_str());
    } else {
      const auto& rtu = config_.rtu;
      ctx_ = modbus_new_rtu(rtu.device.c_str(), rtu.baud, rtu.parity, rtu.data_bits,
                            rtu.stop_bits);
    }
    if (ctx_ == nullptr) return StartResult::failure(modbus_error("modbus: cannot create context"));
  }
  std::uint32_t sec = 0;
  std::uint32_t usec = 0;
  split(config_.response_timeout, sec, usec);
  if (modbus_set_slave(ctx_, config_.slave_id) != 0 ||
      modbus_set_response_timeout(ctx_, sec, usec) != 0) {
    return StartResult::failure(modbus_error("modbus: cannot configure context"));
  }
  split(config_.byte_timeout, sec, usec);
  if (modbus_set_byte_timeout(ctx_, sec, usec) != 0) {
    return StartResult::failure(modbus_error("modbus: cannot set byte timeout"));
  }
  {
    const std::lock_guard lock(stop_mutex_);
    stop_requested_ = false;
  }
  thread_ = std::thread([this] { run(); });
  pthread_setname_np(thread_.native_handle(), "mrd-modbus");
  return StartResult::success();
}

void ModbusBackend::stop() {
  {
    const std::lock_guard lock(stop_mutex_);
    stop_requested_ = true;
  }
  stop_cv_.notify_all();
  if (thread_.joinable()) thread_.join();
}

std::optional<DisplacementSample> ModbusBackend::latest() { return samples_.pop_latest(); }

IoStatus ModbusBackend::write_setpoint(double amps) {
  const EncodeResult encoded = encode_register(amps, config_.registers.setpoint);
  if (encoded.status != CodecStatus::kOk) return IoStatus::kInvalidArgument;
  setpoints_.publish(encoded);
  return connected() ? IoStatus::kOk : IoStatus::kNotConnected;
}

std::optional<CurrentReading> ModbusBackend::measured() { return feedback_.take(); }

ModbusCounters ModbusBackend::counters() const {
  const auto get = [](const std::atomic<std::uint64_t>& c) {
    return c.load(std::memory_order_relaxed);
  };
  const auto& c = counters_;
  return {get(c.connects),    get(c.connect_failures),    get(c.disconnects),
          get(c.reads_ok),    get(c.read_errors),         get(c.timeouts),
          get(c.exception_responses), get(c.decode_errors), get(c.writes_ok),
          get(c.write_errors), get(c.samples_dropped)};
}

bool ModbusBackend::wait_until(steady_clock::time_point deadline) {
  std::unique_lock lock(stop_mutex_);
  return !stop_cv_.wait_until(lock, deadline, [this] { return stop_requested_; });
}

void ModbusBackend::run() {
  auto backoff = config_.reconnect_min;
  bool linked = false;
  auto next_poll = steady_clock::now();
  const auto back_off = [&] {
    const bool go_on = wait_until(steady_clock::now() + backoff);
    backoff = std::min(backoff * 2, config_.reconnect_max);
    return go_on;
  };

  while (wait_until(next_poll)) {
    if (!linked) {
      if (modbus_connect(ctx_) != 0) {
        last_errno_.store(errno, std::memory_order_relaxed);
        bump(counters_.connect_failures);
        if (!back_off()) break;
        next_poll = steady_clock::now();
        continue;
      }
      linked = true;
      connected_.store(true, std::memory_order_relaxed);
      bump(counters_.connects);
    }

    const Outcome outcome = poll_once();
    if (outcome == Outcome::kLinkFailed) {
      modbus_close(ctx_);
      linked = false;
      connected_.store(false, std::memory_order_relaxed);
      bump(counters_.disconnects);
      if (!back_off()) break;
      next_poll = steady_clock::now();
      continue;
    }
    if (outcome == Outcome::kOk) backoff = config_.reconnect_min;
    // Fixed rate without catch-up bursts: after an overrun, the next poll starts now.
    next_poll = std::max(next_poll + config_.poll_period, steady_clock::now());
  }

  if (linked) modbus_close(ctx_);
  connected_.store(false, std::memory_order_relaxed);
}

ModbusBackend::Outcome ModbusBackend::classify_failure(std::atomic<std::uint64_t>& counter) {
  const int err = errno;
  last_errno_.store(err, std::memory_order_relaxed);
  bump(counter);
  if (is_exception_response(err)) {
    bump(counters_.exception_responses);
    return Outcome::kDeviceRefused;
  }
  if (err == ETIMEDOUT) bump(counters_.timeouts);
  return Outcome::kLinkFailed;
}

ModbusBackend::Outcome ModbusBackend::write_pending_setpoint() {
  if (auto newest = setpoints_.take()) pending_setpoint_ = newest;
  if (!pending_setpoint_) return Outcome::kOk;
  const auto words = pending_setpoint_->view();
  const int address = config_.registers.setpoint_address;
  const int rc = words.size() == 1
                     ? modbus_write_register(ctx_, address, words[0])
                     : modbus_write_registers(ctx_, address, static_cast<int>(words.size()),
                                              words.data());
  const Outcome outcome = rc < 0 ? classify_failure(counters_.write_errors) : Outcome::kOk;
  // Kept for after a reconnect; a value the device refuses is dropped, not retried forever.
  if (outcome != Outcome::kLinkFailed) pending_setpoint_.reset();
  if (outcome == Outcome::kOk) bump(counters_.writes_ok);
  return outcome;
}

ModbusBackend::Outcome ModbusBackend::read_words(int address, RegisterKind kind,
                                                 std::size_t count, std::uint16_t* out) {
  const int n = static_cast<int>(count);
  const int rc = kind == RegisterKind::kInput ? modbus_read_input_registers(ctx_, address, n, out)
                                              : modbus_read_registers(ctx_, address, n, out);
  if (rc != n) {
    if (rc >= 0) errno = EMBBADDATA;  // a short answer is a corrupt frame
    return classify_failure(counters_.read_errors);
  }
  bump(counters_.reads_ok);
  return Outcome::kOk;
}

ModbusBackend::Outcome ModbusBackend::poll_once() {
  const RegisterMap& map = config_.registers;
  // The command goes first: its latency matters more than the sample's.
  const Outcome written = write_pending_setpoint();
  if (written == Outcome::kLinkFailed) return written;

  std::array<std::uint16_t, 2> words{};
  const std::size_t n = word_count(map.lvdt.type);
  if (const Outcome o = read_words(map.lvdt_address, map.lvdt_kind, n, words.data());
      o != Outcome::kOk) {
    return o;
  }
  const DecodeResult decoded = decode_register({words.data(), n}, map.lvdt);
  DisplacementSample sample{decoded.value, clock_.now(), ++sequence_, kSampleValid};
  if (decoded.status != CodecStatus::kOk) {
    sample.flags = kSampleCorrupted;
    bump(counters_.decode_errors);
  }
  if (!samples_.try_push(sample)) bump(counters_.samples_dropped);

  if (!map.has_current_feedback) return written;
  const std::size_t m = word_count(map.current_feedback.type);
  if (const Outcome o = read_words(map.current_feedback_address, map.current_feedback_kind, m,
                                   words.data());
      o != Outcome::kOk) {
    return o;
  }
  const DecodeResult current = decode_register({words.data(), m}, map.current_feedback);
  if (current.status != CodecStatus::kOk) {
    bump(counters_.decode_errors);
    return written;
  }
  feedback_.publish({current.value, clock_.now()});
  return written;
}

}  // namespace mrd::hal::modbus
