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
#include "hal/event_counters.hpp"
#include "hal/io_thread.hpp"
#include "hal/latest_mailbox.hpp"
#include "hal/sample_channel.hpp"
#include "hal/sample_source.hpp"
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

// LVDT, current driver and (with use_demand, use_load_cell) force mode's demand and load cell
// on raw SocketCAN, frames as in hal/can/mrd.dbc; each sample channel is a SampleSource of its
// own (lvdt(), demand(), load_cell()). A receive thread
// blocks in recv() with SO_RCVTIMEO, decodes our ids and the error frames, and hands samples
// to the loop through each channel's SPSC ring. Transmission happens on the caller's thread: one
// non-blocking send() per setpoint, no thread hop. Bus-off handling: see BusOffPolicy.
class SocketCanBackend final : public CurrentDriver {
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

  // LVDT_Displacement frames as samples in m (see on_sample_frame).
  [[nodiscard]] SampleSource& lvdt() { return lvdt_.samples; }
  // Force_Demand frames (with use_demand) as samples in N, judged as the LVDT's are.
  [[nodiscard]] SampleSource& demand() { return demand_.samples; }
  // Load_Cell frames (with use_load_cell) as samples in N, judged as the LVDT's are.
  [[nodiscard]] SampleSource& load_cell() { return load_cell_.samples; }
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
  // A sample channel on the bus: the samples for the loop, and its frames' rolling counter and
  // good-frame count.
  struct FrameChannel {
    SampleChannel samples;
    CanEvent good_frames;
    RollingCounterCheck counter;  // receive thread only
  };

  void run();
  void on_frame(const can_frame& frame);
  void on_feedback(std::span<const std::uint8_t> data, std::uint32_t id);
  // The one reaction of a sample channel to a decoded frame; `fault` is the sender's own bit
  // saying its value is unusable.
  void on_sample_frame(FrameChannel& channel, DecodeStatus status, double value, bool fault);
  bool count_rejection(DecodeStatus status);  // true when the frame is unusable

  SocketCanConfig config_;
  const Clock& clock_;
  int fd_ = -1;

  // Receive thread only.
  BusOffPolicy bus_off_;
  RollingCounterCheck feedback_counter_;

  // Loop thread only.
  std::uint8_t tx_counter_ = 0;

  FrameChannel lvdt_{.good_frames = CanEvent::kLvdtFrames};
  FrameChannel demand_{.good_frames = CanEvent::kDemandFrames};
  FrameChannel load_cell_{.good_frames = CanEvent::kLoadCellFrames};
  LatestMailbox<CurrentReading> feedback_;
  std::atomic<int> feedback_fault_{-1};  // -1 unknown, 0 ok, 1 fault
  std::atomic<bool> enable_{false};
  std::atomic<int> last_send_errno_{0};  // 0 once a send succeeds again
  std::atomic<Timestamp::rep> tx_allowed_from_{Timestamp::min().count()};
  EventCounters<CanEvent> counters_;
  IoThread thread_;  // last: stopped first on destruction
};

}  // namespace mrd::hal::can
