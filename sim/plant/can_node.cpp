#include "sim/plant/can_node.hpp"

#include <linux/can/error.h>
#include <linux/can/raw.h>
#include <net/if.h>
#include <sys/socket.h>
#include <sys/time.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <fstream>

namespace mrd::plant {

namespace {

canid_t wire_id(std::uint32_t id, bool extended) { return extended ? (id | CAN_EFF_FLAG) : id; }

can_frame to_wire(const hal::can::Frame& f, bool extended) {
  can_frame frame{};
  frame.can_id = wire_id(f.id, extended);
  frame.len = static_cast<std::uint8_t>(hal::can::kFrameLength);
  std::memcpy(frame.data, f.data.data(), hal::can::kFrameLength);
  return frame;
}

enum Published { kLvdtSent, kLvdtLost, kFeedbackSent, kErrorFrames, kTxErrors };

}  // namespace

CanNode::CanNode(hal::can::SocketCanConfig ids, std::string interface, bool feedback,
                 std::string fault_pull, std::uint32_t seed)
    : ids_(std::move(ids)),
      interface_(std::move(interface)),
      feedback_(feedback),
      fault_pull_(std::move(fault_pull)),
      rng_(seed ^ 0x2545f4914f6cdd1dULL) {}

CanNode::~CanNode() { stop(); }

hal::StartResult CanNode::start() {
  const std::string where = "plant can (" + interface_ + ")";
  const int fd = socket(PF_CAN, SOCK_RAW | SOCK_CLOEXEC, CAN_RAW);
  if (fd < 0) return hal::StartResult::failure(hal::errno_text(where + ": socket(PF_CAN) failed"));
  const unsigned ifindex = if_nametoindex(interface_.c_str());
  const can_filter filter{wire_id(ids_.command_id, ids_.extended_ids),
                          (ids_.extended_ids ? CAN_EFF_MASK : CAN_SFF_MASK) | CAN_EFF_FLAG | CAN_RTR_FLAG};
  const timeval tv{0, 50'000};
  sockaddr_can addr{};
  addr.can_family = AF_CAN;
  addr.can_ifindex = static_cast<int>(ifindex);
  if (ifindex == 0 || setsockopt(fd, SOL_CAN_RAW, CAN_RAW_FILTER, &filter, sizeof filter) != 0 ||
      setsockopt(fd, SOL_SOCKET, SO_RCVTIMEO, &tv, sizeof tv) != 0 ||
      bind(fd, reinterpret_cast<const sockaddr*>(&addr), sizeof addr) != 0) {
    const auto r = hal::StartResult::failure(hal::errno_text(where + ": cannot open the interface"));
    close(fd);
    return r;
  }
  fd_ = fd;
  set_fault_pull(false);
  thread_.start("plant-can-rx", [this] { run(); });
  return hal::StartResult::success();
}

void CanNode::stop() {
  thread_.stop();
  if (fd_ >= 0) close(fd_);
  fd_ = -1;
}

CanNodeCounters CanNode::counters() const {
  return {published_[kLvdtSent].load(),    published_[kLvdtLost].load(), published_[kFeedbackSent].load(),
          published_[kErrorFrames].load(), commands_.load(),            bad_commands_.load(),
          published_[kTxErrors].load()};
}

void CanNode::transmit(const can_frame& frame) {
  if (::send(fd_, &frame, sizeof frame, MSG_DONTWAIT) != static_cast<ssize_t>(sizeof frame)) {
    ++tx_errors_;
  }
}

void CanNode::send_error(canid_t error_class, std::uint8_t controller_status) {
  can_frame frame{};
  frame.can_id = CAN_ERR_FLAG | error_class;
  frame.len = CAN_ERR_DLC;
  frame.data[1] = controller_status;
  transmit(frame);
  ++error_frames_;
}

void CanNode::set_fault_pull(bool fault) {
  if (fault_pull_.empty() || pull_state_ == (fault ? 1 : 0)) return;
  std::ofstream(fault_pull_) << (fault ? "pull-up" : "pull-down");
  pull_state_ = fault ? 1 : 0;
}

std::optional<hal::can::Frame> demand_frame(std::uint32_t id, double demand, const ActiveFaults& faults,
                                            std::uint8_t& counter) {
  if (faults.has(FaultKind::kDemandStale)) return std::nullopt;
  const auto d = hal::can::encode_demand(id, {demand, faults.has(FaultKind::kDemandInvalid), counter});
  if (d.status != hal::can::EncodeStatus::kOk) return std::nullopt;
  counter = static_cast<std::uint8_t>((counter + 1) & 0x0F);
  return d.frame;
}

void CanNode::send(double t, const SensorReadings& readings, const ActiveFaults& faults) {
  using hal::can::EncodeStatus;
  const double dt = t - last_t_;
  last_t_ = t;

  if (faults.has(FaultKind::kErrorFrames)) {
    error_credit_ += faults.value_of(FaultKind::kErrorFrames) * dt;
    for (; error_credit_ >= 1.0; error_credit_ -= 1.0) send_error(CAN_ERR_CRTL, CAN_ERR_CRTL_RX_WARNING);
  } else {
    error_credit_ = 0.0;
  }
  if (faults.has(FaultKind::kBusOff) && !bus_off_sent_) send_error(CAN_ERR_BUSOFF, 0);
  bus_off_sent_ = faults.has(FaultKind::kBusOff);

  // The LVDT conditioner: one frame per period, counter +1 per frame it means to send.
  const bool repeat = faults.has(FaultKind::kBadCounter);
  const auto counter = repeat ? static_cast<std::uint8_t>((lvdt_counter_ + 15) & 0x0F) : lvdt_counter_;
  if (!repeat) lvdt_counter_ = static_cast<std::uint8_t>((lvdt_counter_ + 1) & 0x0F);
  const auto encoded = hal::can::encode_lvdt(ids_.lvdt_id, {readings.lvdt, faults.has(FaultKind::kSensorFault), counter});
  std::uniform_real_distribution<double> uniform(0.0, 100.0);
  const bool lost = faults.has(FaultKind::kLvdtSilent) ||
                    (faults.has(FaultKind::kFrameLoss) && uniform(rng_) < faults.value_of(FaultKind::kFrameLoss));
  if (encoded.status == EncodeStatus::kOk && !lost) {
    can_frame frame = to_wire(encoded.frame, ids_.extended_ids);
    if (faults.has(FaultKind::kBadChecksum)) frame.data[7] ^= 0x5A;
    const double delay = faults.has(FaultKind::kDelay) ? faults.value_of(FaultKind::kDelay) : 0.0;
    delayed_.push_back({t + delay, frame});
  } else if (lost) {
    ++lvdt_lost_;
  }
  while (!delayed_.empty() && delayed_.front().due <= t + 1e-9) {
    transmit(delayed_.front().frame);
    delayed_.pop_front();
    ++lvdt_sent_;
  }

  // The coil driver's feedback, and its fault line.
  const bool fault = faults.has(FaultKind::kDriverFault);
  set_fault_pull(fault);
  if (feedback_) {
    const auto fb = hal::can::encode_feedback(ids_.feedback_id, {readings.coil_current, fault, feedback_counter_});
    feedback_counter_ = static_cast<std::uint8_t>((feedback_counter_ + 1) & 0x0F);
    if (fb.status == EncodeStatus::kOk) {
      transmit(to_wire(fb.frame, ids_.extended_ids));
      ++feedback_sent_;
    }
  }
  // The outer controller of force mode.
  if (ids_.use_demand && readings.demand) {
    if (const auto frame = demand_frame(ids_.demand_id, *readings.demand, faults, demand_counter_)) {
      transmit(to_wire(*frame, ids_.extended_ids));
    }
  }
  published_[kLvdtSent].store(lvdt_sent_, std::memory_order_relaxed);
  published_[kLvdtLost].store(lvdt_lost_, std::memory_order_relaxed);
  published_[kFeedbackSent].store(feedback_sent_, std::memory_order_relaxed);
  published_[kErrorFrames].store(error_frames_, std::memory_order_relaxed);
  published_[kTxErrors].store(tx_errors_, std::memory_order_relaxed);
}

void CanNode::send_load_cell(double force) {
  if (!ids_.use_load_cell) return;
  const auto f = hal::can::encode_load_cell(ids_.load_cell_id, {force, false, load_cell_counter_});
  load_cell_counter_ = static_cast<std::uint8_t>((load_cell_counter_ + 1) & 0x0F);
  if (f.status == hal::can::EncodeStatus::kOk) transmit(to_wire(f.frame, ids_.extended_ids));
}

void CanNode::run() {
  can_frame frame{};
  while (!thread_.stop_requested()) {
    if (recv(fd_, &frame, sizeof frame, 0) != static_cast<ssize_t>(sizeof frame)) continue;
    const bool extended = (frame.can_id & CAN_EFF_FLAG) != 0;
    const std::uint32_t id = frame.can_id & (extended ? CAN_EFF_MASK : CAN_SFF_MASK);
    const auto d = hal::can::decode_command(id, {frame.data, std::min<std::size_t>(frame.len, 8)},
                                            ids_.command_id, &command_counter_);
    if (!hal::can::carries_values(d.status)) {
      bad_commands_.fetch_add(1, std::memory_order_relaxed);
      continue;
    }
    setpoint_.store(d.value.setpoint, std::memory_order_relaxed);
    enable_.store(d.value.enable, std::memory_order_relaxed);
    commands_.fetch_add(1, std::memory_order_relaxed);
  }
}

}  // namespace mrd::plant
