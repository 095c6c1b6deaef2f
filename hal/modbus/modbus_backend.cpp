#include "hal/modbus/modbus_backend.hpp"

#include <modbus/modbus.h>
#include <algorithm>
#include <array>
#include <limits>
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

std::string modbus_error(const char* what) {
  return std::string(what) + ": " + modbus_strerror(errno);
}

}  // namespace

std::string_view to_string(ModbusEvent e) {
  switch (e) {
    case ModbusEvent::kConnects: return "connects";
    case ModbusEvent::kConnectFailures: return "connect_failures";
    case ModbusEvent::kDisconnects: return "disconnects";
    case ModbusEvent::kReadsOk: return "reads_ok";
    case ModbusEvent::kReadErrors: return "read_errors";
    case ModbusEvent::kTimeouts: return "timeouts";
    case ModbusEvent::kExceptionResponses: return "exception_responses";
    case ModbusEvent::kDecodeErrors: return "decode_errors";
    case ModbusEvent::kWritesOk: return "writes_ok";
    case ModbusEvent::kWriteErrors: return "write_errors";
    case ModbusEvent::kWritesRefused: return "writes_refused";
    case ModbusEvent::kSamplesDropped: return "samples_dropped";
    case ModbusEvent::kCount: break;
  }
  return "unknown";
}

ModbusBackend::ModbusBackend(ModbusConfig config, const Clock& clock)
    : config_(std::move(config)), clock_(clock) {}

ModbusBackend::~ModbusBackend() {
  stop();
  if (ctx_ != nullptr) modbus_free(ctx_);
}

StartResult ModbusBackend::start() {
  if (thread_.running()) return StartResult::failure("modbus: already started");
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
  // A TCP connect waits up to the response timeout too; a back-off wait beats on its own.
  thread_.set_max_silence(longest_poll() + IoThread::kBeatSlice);
  thread_.start("mrd-modbus", [this] { run(); });
  return StartResult::success();
}

void ModbusBackend::stop() { thread_.stop(); }

std::string ModbusBackend::endpoint() const {
  const std::string slave = " (slave " + std::to_string(config_.slave_id) + ")";
  if (config_.transport == Transport::kTcp) return config_.tcp.host + ":" + std::to_string(config_.tcp.port) + slave;
  const RtuConfig& rtu = config_.rtu;
  return rtu.device + " " + std::to_string(rtu.baud) + " " + std::to_string(rtu.data_bits) + rtu.parity +
         std::to_string(rtu.stop_bits) + slave;
}

std::optional<std::string> ModbusBackend::link_problem() const {
  if (connected()) return std::nullopt;
  const ModbusCounters c = counters();
  const std::uint64_t attempts = c[ModbusEvent::kConnectFailures];
  if (attempts == 0 && c[ModbusEvent::kDisconnects] == 0) return std::nullopt;
  std::string text = endpoint() + ": " + modbus_strerror(last_errno());
  if (attempts > 0) text += ", " + std::to_string(attempts) + " failed connect attempt" + (attempts == 1 ? "" : "s");
  text += c[ModbusEvent::kConnects] == 0 ? ", never connected" : ", link lost";
  return text;
}

IoStatus ModbusBackend::write_setpoint(double amps) {
  const EncodeResult encoded = encode_register(amps, config_.registers.setpoint);
  if (encoded.status != CodecStatus::kOk) return IoStatus::kInvalidArgument;
  setpoints_.publish(encoded);
  return connected() ? IoStatus::kOk : IoStatus::kNotConnected;
}

std::optional<CurrentReading> ModbusBackend::measured() { return feedback_.take(); }

void ModbusBackend::run() {
  auto backoff = config_.reconnect_min;
  bool linked = false;
  auto next_poll = steady_clock::now();
  const auto back_off = [&] {
    const bool go_on = thread_.wait_for(backoff);
    backoff = std::min(backoff * 2, config_.reconnect_max);
    return go_on;
  };

  while (thread_.wait_until(next_poll)) {
    thread_.beat();
    if (!linked) {
      if (modbus_connect(ctx_) != 0) {
        last_errno_.store(errno, std::memory_order_relaxed);
        counters_.bump(ModbusEvent::kConnectFailures);
        if (!back_off()) break;
        next_poll = steady_clock::now();
        continue;
      }
      linked = true;
      connected_.store(true, std::memory_order_relaxed);
      counters_.bump(ModbusEvent::kConnects);
    }

    const Outcome outcome = poll_once();
    if (outcome == Outcome::kLinkFailed) {
      modbus_close(ctx_);
      linked = false;
      connected_.store(false, std::memory_order_relaxed);
      counters_.bump(ModbusEvent::kDisconnects);
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

ModbusBackend::Outcome ModbusBackend::classify_failure(ModbusEvent counter) {
  const int err = errno;
  last_errno_.store(err, std::memory_order_relaxed);
  counters_.bump(counter);
  if (is_exception_response(err)) {
    counters_.bump(ModbusEvent::kExceptionResponses);
    return Outcome::kDeviceRefused;
  }
  if (err == ETIMEDOUT) counters_.bump(ModbusEvent::kTimeouts);
  return Outcome::kLinkFailed;
}

ModbusBackend::Outcome ModbusBackend::write_pending_setpoint() {
  if (auto newest = setpoints_.take()) {
    pending_setpoint_ = newest;
    taken_.fetch_add(1, std::memory_order_relaxed);
  }
  if (!pending_setpoint_) return Outcome::kOk;
  const auto words = pending_setpoint_->view();
  const int address = config_.registers.setpoint_address;
  const int rc = words.size() == 1
                     ? modbus_write_register(ctx_, address, words[0])
                     : modbus_write_registers(ctx_, address, static_cast<int>(words.size()),
                                              words.data());
  const Outcome outcome = rc < 0 ? classify_failure(ModbusEvent::kWriteErrors) : Outcome::kOk;
  // Kept for after a reconnect; a value the device refuses is dropped, not retried forever.
  if (outcome != Outcome::kLinkFailed) pending_setpoint_.reset();
  if (outcome == Outcome::kOk) counters_.bump(ModbusEvent::kWritesOk);
  if (outcome == Outcome::kDeviceRefused) counters_.bump(ModbusEvent::kWritesRefused);
  return outcome;
}

ModbusBackend::Outcome ModbusBackend::read_words(int address, RegisterKind kind,
                                                 std::size_t count, std::uint16_t* out) {
  const int n = static_cast<int>(count);
  const int rc = kind == RegisterKind::kInput ? modbus_read_input_registers(ctx_, address, n, out)
                                              : modbus_read_registers(ctx_, address, n, out);
  if (rc != n) {
    if (rc >= 0) errno = EMBBADDATA;  // a short answer is a corrupt frame
    return classify_failure(ModbusEvent::kReadErrors);
  }
  counters_.bump(ModbusEvent::kReadsOk);
  return Outcome::kOk;
}

void ModbusBackend::push(SampleChannel& channel, const Sample& sample) {
  if (!channel.push(sample)) counters_.bump(ModbusEvent::kSamplesDropped);
}

void ModbusBackend::push_sample(std::span<const std::uint16_t> words, const RegisterFormat& format,
                                std::uint32_t sequence, SampleChannel& channel) {
  const DecodeResult decoded = decode_register(words, format);
  Sample sample{decoded.value, clock_.now(), sequence, kSampleValid};
  if (decoded.status != CodecStatus::kOk) {
    sample.flags = kSampleCorrupted;
    counters_.bump(ModbusEvent::kDecodeErrors);
  }
  push(channel, sample);
}

ModbusBackend::Outcome ModbusBackend::read_sample(int address, RegisterKind kind, const RegisterFormat& format,
                                                  SampleChannel& channel) {
  std::array<std::uint16_t, 2> words{};
  const std::size_t n = word_count(format.type);
  if (const Outcome o = read_words(address, kind, n, words.data()); o != Outcome::kOk) return o;
  push_sample({words.data(), n}, format, channel.next_sequence(), channel);
  return Outcome::kOk;
}

ModbusBackend::Outcome ModbusBackend::read_demand() {
  const RegisterMap& map = config_.registers;
  if (!map.has_demand_counter()) {
    return read_sample(map.demand_address, map.demand_kind, map.demand, demand_);
  }
  // words: the value's one or two, then the counter's.
  std::array<std::uint16_t, 3> words{};
  const std::size_t n = word_count(map.demand.type);
  const int value_end = map.demand_address + static_cast<int>(n);
  Outcome o = Outcome::kOk;
  if (map.demand_counter_address == value_end) {
    o = read_words(map.demand_address, map.demand_kind, n + 1, words.data());
  } else if (map.demand_counter_address + 1 == map.demand_address) {
    std::array<std::uint16_t, 3> ahead{};  // counter first on the device
    o = read_words(map.demand_counter_address, map.demand_kind, n + 1, ahead.data());
    std::copy_n(ahead.begin() + 1, n, words.begin());
    words[n] = ahead[0];
  } else {
    // Counter first: an outer controller writes the value, then counts, so a value read after
    // the counter is at least as new as it. The other order could pair a new counter with the
    // old value and then never take the new one.
    o = read_words(map.demand_counter_address, map.demand_kind, 1, &words[n]);
    if (o == Outcome::kOk) o = read_words(map.demand_address, map.demand_kind, n, words.data());
  }
  if (o != Outcome::kOk) return o;
  const std::uint16_t counter = words[n];
  // The first count only sets the reference: whatever a stopped outer controller left in the
  // registers before this start is not a demand. A change is.
  const bool first = !demand_counter_;
  if (demand_counter_ == counter) return Outcome::kOk;  // nothing new since the last poll
  demand_counter_ = counter;
  if (!first) push_sample({words.data(), n}, map.demand, counter, demand_);
  return Outcome::kOk;
}

ModbusBackend::Outcome ModbusBackend::poll_once() {
  const RegisterMap& map = config_.registers;
  // The command goes first: its latency matters more than the sample's.
  const Outcome written = write_pending_setpoint();
  if (written == Outcome::kLinkFailed) return written;

  if (const Outcome o = read_sample(map.lvdt_address, map.lvdt_kind, map.lvdt, lvdt_); o != Outcome::kOk) return o;
  if (map.has_demand) {
    if (const Outcome o = read_demand(); o != Outcome::kOk) return o;
  }
  if (map.has_current_feedback) {
    if (const Outcome o = read_current_feedback(); o != Outcome::kOk) return o;
  }
  // Last, and never at the cost of the rest: a device that refuses the load cell's registers
  // leaves the LVDT, demand and readback read (a refusal there would starve the readback and
  // trip SAFE); the correction gets a corrupted sample and freezes, which is not a fault.
  if (map.has_load_cell) {
    const Outcome o = read_sample(map.load_cell_address, map.load_cell_kind, map.load_cell, load_cell_);
    if (o == Outcome::kLinkFailed) return o;
    if (o == Outcome::kDeviceRefused) {
      push(load_cell_, {std::numeric_limits<double>::quiet_NaN(), clock_.now(), load_cell_.next_sequence(),
                        kSampleCorrupted});
    }
  }
  return written;
}

ModbusBackend::Outcome ModbusBackend::read_current_feedback() {
  const RegisterMap& map = config_.registers;
  std::array<std::uint16_t, 2> words{};
  const std::size_t m = word_count(map.current_feedback.type);
  if (const Outcome o = read_words(map.current_feedback_address, map.current_feedback_kind, m, words.data());
      o != Outcome::kOk) {
    return o;
  }
  const DecodeResult current = decode_register({words.data(), m}, map.current_feedback);
  if (current.status != CodecStatus::kOk) {
    counters_.bump(ModbusEvent::kDecodeErrors);
    return Outcome::kOk;
  }
  feedback_.publish({current.value, clock_.now()});
  return Outcome::kOk;
}

}  // namespace mrd::hal::modbus
