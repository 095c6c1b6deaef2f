#pragma once

#include <atomic>
#include <condition_variable>
#include <cstdint>
#include <mutex>
#include <optional>
#include <thread>

#include "hal/clock.hpp"
#include "hal/current_driver.hpp"
#include "hal/displacement_source.hpp"
#include "hal/latest_mailbox.hpp"
#include "hal/modbus/modbus_config.hpp"
#include "hal/spsc_ring.hpp"
#include "hal/status.hpp"

struct _modbus;  // libmodbus's modbus_t, kept out of our headers

namespace mrd::hal::modbus {

// Counts since start(); a snapshot the loop or telemetry can read at any time.
struct ModbusCounters {
  std::uint64_t connects = 0;             // successful (re)connections
  std::uint64_t connect_failures = 0;
  std::uint64_t disconnects = 0;          // link dropped after an I/O failure
  std::uint64_t reads_ok = 0;
  std::uint64_t read_errors = 0;          // includes timeouts
  std::uint64_t timeouts = 0;
  std::uint64_t exception_responses = 0;  // the device answered with a Modbus exception
  std::uint64_t decode_errors = 0;        // the words arrived but made no usable value
  std::uint64_t writes_ok = 0;
  std::uint64_t write_errors = 0;
  std::uint64_t samples_dropped = 0;      // the loop did not drain the ring in time
};

// LVDT and current driver behind one Modbus device (RTU or TCP). All libmodbus I/O runs in one
// thread that owns the only modbus_t: libmodbus blocks, and an RTU read alone takes ~1.6 ms at
// 115200 baud, longer than a 1 kHz period. The loop's calls only touch lock-free buffers.
//
// Link policy: any transport failure (timeout, reset, bad frame) closes the link and reconnects
// after a back-off that doubles from reconnect_min to reconnect_max and resets after the next
// good transaction. A Modbus exception response is a device answer, not a link failure: it is
// counted and the link kept. stop() returns within one response timeout.
class ModbusBackend final : public DisplacementSource, public CurrentDriver {
 public:
  ModbusBackend(ModbusConfig config, const Clock& clock);
  ~ModbusBackend() override;
  ModbusBackend(const ModbusBackend&) = delete;
  ModbusBackend& operator=(const ModbusBackend&) = delete;

  // Validates the config, creates the context and starts the I/O thread. The device need not
  // be reachable yet: connecting is the thread's job, with back-off.
  [[nodiscard]] StartResult start();
  void stop();

  [[nodiscard]] std::optional<DisplacementSample> latest() override;
  // Queues the newest setpoint for the I/O thread. kInvalidArgument when it cannot be encoded;
  // kNotConnected when queued but the link is down (it is written after reconnecting).
  IoStatus write_setpoint(double amps) override;
  [[nodiscard]] std::optional<CurrentReading> measured() override;

  [[nodiscard]] ModbusCounters counters() const;
  [[nodiscard]] bool connected() const { return connected_.load(std::memory_order_relaxed); }
  [[nodiscard]] int last_errno() const { return last_errno_.load(std::memory_order_relaxed); }

 private:
  enum class Outcome { kOk, kDeviceRefused, kLinkFailed };

  void run();
  Outcome poll_once();
  Outcome write_pending_setpoint();
  Outcome read_words(int address, RegisterKind kind, std::size_t count, std::uint16_t* out);
  Outcome classify_failure(std::atomic<std::uint64_t>& counter);
  bool wait_until(std::chrono::steady_clock::time_point deadline);  // false when stopping

  ModbusConfig config_;
  const Clock& clock_;
  _modbus* ctx_ = nullptr;  // used only by thread_ while it runs

  SpscRing<DisplacementSample, 64> samples_;
  LatestMailbox<EncodeResult> setpoints_;
  LatestMailbox<CurrentReading> feedback_;
  std::optional<EncodeResult> pending_setpoint_;  // I/O thread only
  std::uint32_t sequence_ = 0;                    // I/O thread only

  std::atomic<bool> connected_{false};
  std::atomic<int> last_errno_{0};
  struct AtomicCounters {
    std::atomic<std::uint64_t> connects{0}, connect_failures{0}, disconnects{0}, reads_ok{0},
        read_errors{0}, timeouts{0}, exception_responses{0}, decode_errors{0}, writes_ok{0},
        write_errors{0}, samples_dropped{0};
  } counters_;

  std::mutex stop_mutex_;
  std::condition_variable stop_cv_;
  bool stop_requested_ = false;  // guarded by stop_mutex_
  std::thread thread_;
};

}  // namespace mrd::hal::modbus
