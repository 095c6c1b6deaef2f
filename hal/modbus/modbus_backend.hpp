#pragma once

#include <atomic>
#include <cstdint>
#include <optional>
#include <span>
#include <string>
#include <string_view>

#include "hal/clock.hpp"
#include "hal/current_driver.hpp"
#include "hal/event_counters.hpp"
#include "hal/io_thread.hpp"
#include "hal/latest_mailbox.hpp"
#include "hal/modbus/modbus_config.hpp"
#include "hal/sample_channel.hpp"
#include "hal/sample_source.hpp"
#include "hal/status.hpp"

struct _modbus;  // libmodbus's modbus_t, kept out of our headers

namespace mrd::hal::modbus {

// What the I/O thread counts since construction.
enum class ModbusEvent : std::uint8_t {
  kConnects,            // successful (re)connections
  kConnectFailures,
  kDisconnects,         // link dropped after an I/O failure
  kReadsOk,
  kReadErrors,          // includes timeouts and exception responses
  kTimeouts,
  kExceptionResponses,  // the device answered with a Modbus exception
  kDecodeErrors,        // the words arrived but made no usable value
  kWritesOk,
  kWriteErrors,
  kWritesRefused,       // of the write errors, the device answered with an exception
  kSamplesDropped,      // the loop did not drain the ring in time
  kCount
};
[[nodiscard]] std::string_view to_string(ModbusEvent e);
using ModbusCounters = EventCounters<ModbusEvent>::Snapshot;

// LVDT, current driver and (with registers.has_demand, has_load_cell) force mode's demand and
// load cell behind one Modbus device (RTU or TCP); each sample channel is a SampleSource of
// its own (lvdt(), demand(), load_cell()). All libmodbus I/O runs in one
// thread that owns the only modbus_t: libmodbus blocks, and an RTU read alone takes ~1.6 ms at
// 115200 baud, longer than a 1 kHz period. The loop's calls only touch lock-free buffers.
//
// Link policy: any transport failure (timeout, reset, bad frame) closes the link and reconnects
// after a back-off that doubles from reconnect_min to reconnect_max and resets after the next
// good transaction. A Modbus exception response is a device answer, not a link failure: it is
// counted and the link kept. stop() returns within one response timeout.
class ModbusBackend final : public CurrentDriver {
 public:
  ModbusBackend(ModbusConfig config, const Clock& clock);
  ~ModbusBackend() override;
  ModbusBackend(const ModbusBackend&) = delete;
  ModbusBackend& operator=(const ModbusBackend&) = delete;

  // Validates the config, creates the context and starts the I/O thread. The device need not
  // be reachable yet: connecting is the thread's job, with back-off.
  [[nodiscard]] StartResult start();
  void stop();

  // The LVDT's registers in m, one sample per poll.
  [[nodiscard]] SampleSource& lvdt() { return lvdt_; }
  // The demand register's value in N (with registers.has_demand). Without a counter register
  // one sample per poll (a value the outer controller stopped updating reads as fresh); with
  // registers.demand_counter_address one per poll that finds the counter changed, its sequence
  // the counter's value.
  [[nodiscard]] SampleSource& demand() { return demand_; }
  // The load cell's registers (with registers.has_load_cell) in N, one sample per poll.
  [[nodiscard]] SampleSource& load_cell() { return load_cell_; }
  // Queues the newest setpoint for the I/O thread. kInvalidArgument when it cannot be encoded;
  // kNotConnected when queued but the link is down (it is written after reconnecting).
  IoStatus write_setpoint(double amps) override;
  [[nodiscard]] std::optional<CurrentReading> measured() override;
  [[nodiscard]] SetpointAcks setpoint_acks() const override {
    return {counters_.get(ModbusEvent::kWritesOk), counters_.get(ModbusEvent::kWritesRefused)};
  }

  // Setpoints taken from the mailbox, within a poll's worst case (longest_poll()).
  [[nodiscard]] std::optional<SetpointHandover> handover() const override {
    return SetpointHandover{taken_.load(std::memory_order_relaxed), longest_poll()};
  }

  [[nodiscard]] ModbusCounters counters() const { return counters_.snapshot(); }
  // Its I/O thread, for the caller's scheduling set-up.
  [[nodiscard]] IoThread& io_thread() { return thread_; }
  [[nodiscard]] bool connected() const { return connected_.load(std::memory_order_relaxed); }
  [[nodiscard]] int last_errno() const { return last_errno_.load(std::memory_order_relaxed); }
  // Where the device is: "127.0.0.1:1502 (slave 1)" or "/dev/ttyUSB0 19200 8N1 (slave 1)".
  [[nodiscard]] std::string endpoint() const;
  // Why the link is down, as mbpoll would say it ("127.0.0.1:1502 (slave 1): Connection refused,
  // 7 connect attempts, never connected"); nullopt while it is up or before the first attempt.
  [[nodiscard]] std::optional<std::string> link_problem() const;
  // Whether the link is down and never came up since start(): the bus, not the device's data.
  [[nodiscard]] bool never_connected() const {
    return !connected() && counters_.get(ModbusEvent::kConnects) == 0 && counters_.get(ModbusEvent::kConnectFailures) > 0;
  }

 private:
  enum class Outcome { kOk, kDeviceRefused, kLinkFailed };
  // A poll's period and its transactions (setpoint, LVDT, demand and counter, readback, load
  // cell), each answered at the last moment: the longest a live thread blocks between beats.
  static constexpr int kMaxTransactions = 6;
  [[nodiscard]] Timestamp longest_poll() const {
    return config_.poll_period + kMaxTransactions * (config_.response_timeout + config_.byte_timeout);
  }

  void run();
  Outcome poll_once();
  Outcome read_current_feedback();
  Outcome write_pending_setpoint();
  Outcome read_words(int address, RegisterKind kind, std::size_t count, std::uint16_t* out);
  Outcome classify_failure(ModbusEvent counter);
  // Reads one value's registers and hands it to the loop on `channel` as its next sample
  // (corrupted when it does not decode).
  Outcome read_sample(int address, RegisterKind kind, const RegisterFormat& format, SampleChannel& channel);
  // The demand, with its counter when it has one: a sample only when the counter moved.
  Outcome read_demand();
  // Queues `sample` on `channel`, counting it when the loop left the ring full.
  void push(SampleChannel& channel, const Sample& sample);
  // Decodes `words` into a sample stamped now and queues it.
  void push_sample(std::span<const std::uint16_t> words, const RegisterFormat& format, std::uint32_t sequence,
                   SampleChannel& channel);

  ModbusConfig config_;
  const Clock& clock_;
  _modbus* ctx_ = nullptr;  // used only by thread_ while it runs

  SampleChannel lvdt_;
  SampleChannel demand_;
  SampleChannel load_cell_;
  LatestMailbox<EncodeResult> setpoints_;
  LatestMailbox<CurrentReading> feedback_;
  std::optional<EncodeResult> pending_setpoint_;  // I/O thread only
  // The counter's value at the last demand taken; kept over a reconnect, so that a demand
  // frozen across an outage is not taken as new. I/O thread only.
  std::optional<std::uint16_t> demand_counter_;

  std::atomic<std::uint64_t> taken_{0};  // setpoints the I/O thread took from setpoints_
  std::atomic<bool> connected_{false};
  std::atomic<int> last_errno_{0};
  EventCounters<ModbusEvent> counters_;
  IoThread thread_;  // last: stopped first on destruction
};

}  // namespace mrd::hal::modbus
