#pragma once

#include <atomic>
#include <cstdint>
#include <optional>
#include <random>
#include <string>
#include <vector>

#include "hal/io_thread.hpp"
#include "hal/modbus/modbus_config.hpp"
#include "hal/status.hpp"
#include "sim/plant/rig.hpp"

struct _modbus;
struct _modbus_mapping_t;

namespace mrd::plant {

struct ModbusServerCounters {
  std::uint64_t connections = 0;
  std::uint64_t requests = 0;
  std::uint64_t answered = 0;
  std::uint64_t unanswered = 0;   // dropped on purpose: loss, stall, silent LVDT
  std::uint64_t exceptions = 0;   // bad_checksum answers
  std::uint64_t setpoints = 0;    // setpoint writes taken
  std::uint64_t restarts = 0;
};

// The rig's Modbus device: a libmodbus server that serves the LVDT (and, when the controller
// reads it, the coil current) in the controller's register layout and takes its setpoint.
// TCP: listens on host:port and serves any number of clients. RTU: on a pty whose other end
// the controller opens through a symlink. All libmodbus I/O runs in one thread; the plant's
// loop hands it values and faults through atomics.
class ModbusServer {
 public:
  ModbusServer(hal::modbus::ModbusConfig layout, std::string host, int port, std::string rtu_link,
               std::uint32_t seed);
  ~ModbusServer();
  ModbusServer(const ModbusServer&) = delete;
  ModbusServer& operator=(const ModbusServer&) = delete;

  // Listens (TCP) or opens the pty (RTU), then starts the thread.
  [[nodiscard]] hal::StartResult start();
  void stop();
  // "127.0.0.1:1502" or "/tmp/mrd-plant-rtu -> /dev/pts/3"
  [[nodiscard]] const std::string& endpoint() const { return endpoint_; }
  [[nodiscard]] int port() const { return port_; }

  // Loop side: this period's LVDT value, coil current and faults.
  // `readings.demand` [N] (none: the plant is not the outer controller) goes to the demand registers
  // when the controller reads them, and counts in its counter register when it has one;
  // demand_stale freezes both, demand_invalid writes the fault's value instead.
  void publish(const SensorReadings& readings, const ActiveFaults& faults);
  // Loop side: the rig's measured force [N] for the load-cell registers, when the controller
  // reads them (force mode's load-cell feedback).
  void publish_load_cell(double force);
  // The newest setpoint the controller wrote [A]; 0 before the first.
  [[nodiscard]] double setpoint() const { return setpoint_.load(std::memory_order_relaxed); }
  [[nodiscard]] ModbusServerCounters counters() const;
  // Its I/O thread, for the caller's scheduling set-up.
  [[nodiscard]] hal::IoThread& io_thread() { return thread_; }

 private:
  bool listen_tcp(std::string& error);
  void close_all();
  void run();
  void serve(int fd);
  void fill_registers();
  void take_setpoint();

  hal::modbus::ModbusConfig layout_;
  std::string host_;
  int port_;
  std::string rtu_link_;
  std::string endpoint_;
  _modbus* ctx_ = nullptr;
  _modbus_mapping_t* map_ = nullptr;
  int listen_fd_ = -1;
  int pty_master_ = -1;
  int pty_slave_ = -1;  // held open so the controller's close does not hang up the master
  std::vector<int> clients_;
  std::mt19937_64 rng_;  // server thread only

  std::atomic<std::uint32_t> lvdt_words_{0};
  std::atomic<std::uint32_t> feedback_words_{0};
  // The demand's words (low half) and its counter (bits 32-47) in one atomic, so that a reply
  // never pairs a new count with the value before it.
  std::atomic<std::uint64_t> demand_state_{0};
  std::atomic<std::uint32_t> load_cell_words_{0};
  std::atomic<double> setpoint_{0.0};
  std::atomic<bool> stall_{false};
  std::atomic<bool> down_{false};
  std::atomic<bool> lvdt_silent_{false};
  std::atomic<bool> corrupt_{false};
  std::atomic<double> loss_{0.0};   // probability
  std::atomic<double> delay_{0.0};  // [s]

  std::atomic<std::uint64_t> connections_{0}, requests_{0}, answered_{0}, unanswered_{0},
      exceptions_{0}, setpoints_{0}, restarts_{0};
  hal::IoThread thread_;
};

}  // namespace mrd::plant
