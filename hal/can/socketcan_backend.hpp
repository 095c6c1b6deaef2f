#pragma once

#include <linux/can.h>

#include <atomic>
#include <cstdint>
#include <optional>
#include <string>
#include <string_view>

#include "hal/can/bus_off_policy.hpp"
#include "hal/can/can_codec.hpp"
#include "hal/can/socketcan_config.hpp"
#include "hal/clock.hpp"
#include "hal/current_driver.hpp"
#include "hal/demand_source.hpp"
#include "hal/displacement_source.hpp"
#include "hal/event_counters.hpp"
#include "hal/io_thread.hpp"
#include "hal/load_cell_source.hpp"
#include "hal/latest_mailbox.hpp"
#include "hal/spsc_ring.hpp"
#include "hal/status.hpp"

namespace mrd::hal::can {

enum class CanEvent : std::uint8_t {
  kLvdtFrames,           // good LVDT frames (including those after a gap)
  kFeedbackFrames,       // good current-feedback frames
  kDemandFrames,         // good Force_Demand frames (force mode; including those after a gap)
  kLoadCellFrames,       // good Load_Cell frames (force mode's optional load cell)
  kWrongDlc,
  kBadChecksum,
  kRepeatedCounter,
  kSequenceGaps,
  kUnexpectedFrames,     // ids the filter should have kept out
  kErrorFrames,
  kBusOff,
  kRestarted,
  kControllerProblems,   // error-warning, error-passive or overflow reports
  kFramesSent,
  kTxErrors,             // send() failed (queue full, interface down)
  kTxInhibited,          // setpoints held back by the bus-off policy
  kSamplesDropped,       // the loop did not drain the ring in time
  kCount
};
[[nodiscard]] std::string_view to_string(CanEvent e);
using CanCounters = EventCounters<CanEvent>::Snapshot;

// LVDT, current driver and (with use_demand) force mode's demand on raw SocketCAN, frames as
// in hal/can/mrd.dbc. A receive thread
// blocks in recv() with SO_RCVTIMEO, decodes our ids and the error frames, and hands samples
// to the loop through the SPSC ring. Transmission happens on the caller's thread: one
// non-blocking send() per setpoint, no thread hop. Bus-off handling: see BusOffPolicy.
class SocketCanBackend final : public DisplacementSource,
                               public CurrentDriver,
                               public DemandSource,
                               public LoadCellSource {
 public:
  SocketCanBackend(SocketCanConfig config, const Clock& clock);
  ~SocketCanBackend() override;
  SocketCanBackend(const SocketCanBackend&) = delete;
  SocketCanBackend& operator=(const SocketCanBackend&) = delete;

  // Opens and binds the socket and starts the receive thread; on failure says why (no CAN in
  // the kernel, no such interface, ...) and leaves the back end inert.
  [[nodiscard]] StartResult start();
  // Runs on `fd`, an open datagram socket carrying one struct can_frame per message, instead of
  // the configured interface: what a test drives the receive thread through (a socketpair
  // standing in for the bus) where the kernel has no CAN. Takes the descriptor.
  [[nodiscard]] StartResult start_on(int fd);
  void stop();

  [[nodiscard]] std::optional<DisplacementSample> latest() override;
  // Force_Demand frames as samples in N, judged as the LVDT's are (see on_value_frame).
  [[nodiscard]] std::optional<DemandSample> latest_demand() override;
  // Load_Cell frames (with use_load_cell) as samples in N, judged as the demand's are.
  [[nodiscard]] std::optional<LoadCellSample> latest_load_cell() override;
  // Sends one Coil_CurrentCommand frame now. kNotConnected before start(), kTxInhibited during
  // bus-off and its hold-off, kInvalidArgument when it does not fit, kIoError if send() fails.
  IoStatus write_setpoint(double amps) override;
  [[nodiscard]] std::optional<CurrentReading> measured() override;

  // The DriverEnable bit carried by later command frames.
  void set_command_enable(bool enabled) { enable_.store(enabled, std::memory_order_relaxed); }
  // The driver's fault bit from its newest feedback frame; nullopt before the first one.
  [[nodiscard]] std::optional<bool> feedback_driver_fault() const;

  [[nodiscard]] CanCounters counters() const { return counters_.snapshot(); }
  // What keeps the link from carrying the loop's data now, as candump and `ip -details link`
  // would show it: an expected frame that never came, a bus-off hold, sends still failing
  // ("can0: no LVDT frame (id 0x110) received, 3 failed sends (last: Network is down)"); nullopt
  // when nothing does. `lvdt` and `feedback` say which frames this link should carry.
  [[nodiscard]] std::optional<std::string> link_problem(bool lvdt, bool feedback) const;
  // Its I/O thread, for the caller's scheduling set-up.
  [[nodiscard]] IoThread& io_thread() { return thread_; }
  [[nodiscard]] bool tx_allowed() const;

 private:
  void run();
  void on_frame(const can_frame& frame);
  void on_lvdt(std::span<const std::uint8_t> data, std::uint32_t id);
  void on_feedback(std::span<const std::uint8_t> data, std::uint32_t id);
  void on_demand(std::span<const std::uint8_t> data, std::uint32_t id);
  void on_load_cell(std::span<const std::uint8_t> data, std::uint32_t id);
  // The one reaction of the sample channels (LVDT, demand) to a decoded frame.
  void on_value_frame(DecodeStatus status, double value, bool fault, CanEvent good,
                      std::uint32_t& sequence, SpscRing<Sample, 64>& ring);
  bool count_rejection(DecodeStatus status);  // true when the frame is unusable

  SocketCanConfig config_;
  const Clock& clock_;
  int fd_ = -1;

  // Receive thread only.
  BusOffPolicy bus_off_;
  RollingCounterCheck lvdt_counter_;
  RollingCounterCheck feedback_counter_;
  RollingCounterCheck demand_counter_;
  RollingCounterCheck load_cell_counter_;
  std::uint32_t sequence_ = 0;
  std::uint32_t demand_sequence_ = 0;
  std::uint32_t load_cell_sequence_ = 0;

  // Loop thread only.
  std::uint8_t tx_counter_ = 0;

  SpscRing<DisplacementSample, 64> samples_;
  SpscRing<DemandSample, 64> demands_;
  SpscRing<LoadCellSample, 64> load_cell_;
  LatestMailbox<CurrentReading> feedback_;
  std::atomic<int> feedback_fault_{-1};  // -1 unknown, 0 ok, 1 fault
  std::atomic<bool> enable_{false};
  std::atomic<int> last_send_errno_{0};  // 0 once a send succeeds again
  std::atomic<Timestamp::rep> tx_allowed_from_{Timestamp::min().count()};
  EventCounters<CanEvent> counters_;
  IoThread thread_;  // last: stopped first on destruction
};

}  // namespace mrd::hal::can
