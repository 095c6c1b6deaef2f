#pragma once

#include <linux/can.h>

#include <atomic>
#include <cstdint>
#include <deque>
#include <optional>
#include <random>
#include <string>

#include "hal/can/can_codec.hpp"
#include "hal/can/socketcan_config.hpp"
#include "hal/io_thread.hpp"
#include "hal/status.hpp"
#include "sim/plant/rig.hpp"

namespace mrd::plant {

struct CanNodeCounters {
  std::uint64_t lvdt_sent = 0;
  std::uint64_t lvdt_lost = 0;      // frame_loss and lvdt_silent
  std::uint64_t feedback_sent = 0;
  std::uint64_t error_frames = 0;
  std::uint64_t commands = 0;       // good command frames
  std::uint64_t bad_commands = 0;   // DLC, checksum or counter wrong
  std::uint64_t tx_errors = 0;
};

// The outer controller's Force_Demand frame this period for `demand` [N], under the demand
// faults: none while demand_stale (and the counter holds: a silent controller counts nothing),
// the DemandInvalid bit while demand_invalid. Advances `counter` (4 bits) per frame sent.
[[nodiscard]] std::optional<hal::can::Frame> demand_frame(std::uint32_t id, double demand, const ActiveFaults& faults,
                                                          std::uint8_t& counter);

// The rig's LVDT conditioner and coil driver on one SocketCAN interface, frames as in
// hal/can/mrd.dbc with the controller's ids. The plant's loop sends the LVDT (and feedback)
// frames each period, with the CAN faults applied; a receive thread takes the command frames.
class CanNode {
 public:
  CanNode(hal::can::SocketCanConfig ids, std::string interface, bool feedback,
          std::string fault_pull, std::uint32_t seed);
  ~CanNode();
  CanNode(const CanNode&) = delete;
  CanNode& operator=(const CanNode&) = delete;

  [[nodiscard]] hal::StartResult start();
  void stop();

  // Loop side, once per period at plant time t [s]: the LVDT and current feedback frames.
  // `readings.demand` [N] (none: the plant is not the outer controller) goes out as a
  // Force_Demand frame when the controller receives it (demand_frame).
  void send(double t, const SensorReadings& readings, const ActiveFaults& faults);
  // Loop side, after send(): the rig's measured force [N] as a Load_Cell frame when the
  // controller receives one (force mode's load-cell feedback).
  void send_load_cell(double force);
  // The newest command: setpoint [A] and DriverEnable; 0 A and off before the first.
  [[nodiscard]] double setpoint() const { return setpoint_.load(std::memory_order_relaxed); }
  [[nodiscard]] bool enabled() const { return enable_.load(std::memory_order_relaxed); }
  [[nodiscard]] CanNodeCounters counters() const;
  // Its I/O thread, for the caller's scheduling set-up.
  [[nodiscard]] hal::IoThread& io_thread() { return thread_; }
  [[nodiscard]] const std::string& interface() const { return interface_; }

 private:
  struct Pending {
    double due;  // [s]
    can_frame frame;
  };
  void transmit(const can_frame& frame);
  void send_error(canid_t error_class, std::uint8_t controller_status);
  void set_fault_pull(bool fault);
  void run();

  hal::can::SocketCanConfig ids_;
  std::string interface_;
  bool feedback_;
  std::string fault_pull_;
  int fd_ = -1;

  // Loop thread only.
  std::mt19937_64 rng_;
  std::uint8_t lvdt_counter_ = 0;
  std::uint8_t feedback_counter_ = 0;
  std::uint8_t demand_counter_ = 0;
  std::uint8_t load_cell_counter_ = 0;
  double error_credit_ = 0.0;
  double last_t_ = 0.0;
  bool bus_off_sent_ = false;
  int pull_state_ = -1;  // -1 unknown, 0 ok, 1 fault
  std::deque<Pending> delayed_;
  std::uint64_t lvdt_sent_ = 0, lvdt_lost_ = 0, feedback_sent_ = 0, error_frames_ = 0, tx_errors_ = 0;
  std::atomic<std::uint64_t> published_[5]{};

  // Receive thread.
  hal::can::RollingCounterCheck command_counter_;
  std::atomic<double> setpoint_{0.0};
  std::atomic<bool> enable_{false};
  std::atomic<std::uint64_t> commands_{0}, bad_commands_{0};
  hal::IoThread thread_;
};

}  // namespace mrd::plant
