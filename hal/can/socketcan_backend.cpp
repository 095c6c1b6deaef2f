#include "hal/can/socketcan_backend.hpp"

#include <linux/can/raw.h>
#include <net/if.h>
#include <sys/socket.h>
#include <sys/time.h>
#include <unistd.h>

#include <array>
#include <cerrno>
#include <cstdio>
#include <cstring>
#include <string>
#include <vector>

namespace mrd::hal::can {

namespace {

canid_t wire_id(std::uint32_t id, bool extended) {
  return extended ? (id | CAN_EFF_FLAG) : id;
}

can_filter exact_filter(std::uint32_t id, bool extended) {
  // Matches the id, its frame format, and data frames only (no RTR).
  const canid_t mask = (extended ? CAN_EFF_MASK : CAN_SFF_MASK) | CAN_EFF_FLAG | CAN_RTR_FLAG;
  return {wire_id(id, extended), mask};
}

}  // namespace

std::string_view to_string(CanEvent e) {
  switch (e) {
    case CanEvent::kLvdtFrames: return "lvdt_frames";
    case CanEvent::kFeedbackFrames: return "feedback_frames";
    case CanEvent::kDemandFrames: return "demand_frames";
    case CanEvent::kLoadCellFrames: return "load_cell_frames";
    case CanEvent::kWrongDlc: return "wrong_dlc";
    case CanEvent::kBadChecksum: return "bad_checksum";
    case CanEvent::kRepeatedCounter: return "repeated_counter";
    case CanEvent::kSequenceGaps: return "sequence_gaps";
    case CanEvent::kUnexpectedFrames: return "unexpected_frames";
    case CanEvent::kErrorFrames: return "error_frames";
    case CanEvent::kBusOff: return "bus_off";
    case CanEvent::kRestarted: return "restarted";
    case CanEvent::kControllerProblems: return "controller_problems";
    case CanEvent::kFramesSent: return "frames_sent";
    case CanEvent::kTxErrors: return "tx_errors";
    case CanEvent::kTxInhibited: return "tx_inhibited";
    case CanEvent::kSamplesDropped: return "samples_dropped";
    case CanEvent::kCount: break;
  }
  return "unknown";
}

SocketCanBackend::SocketCanBackend(SocketCanConfig config, const Clock& clock)
    : config_(std::move(config)), clock_(clock), bus_off_(config_.bus_off_hold_off) {}

SocketCanBackend::~SocketCanBackend() { stop(); }

StartResult SocketCanBackend::start() {
  if (fd_ >= 0) return StartResult::failure("can: already started");
  if (const auto report = config_.validate(); !report.ok()) {
    return StartResult::failure("can config:\n" + report.to_string());
  }
  const std::string where = "can (" + config_.interface + ")";
  const int fd = socket(PF_CAN, SOCK_RAW | SOCK_CLOEXEC, CAN_RAW);
  if (fd < 0) {
    return StartResult::failure(errno_text(where + ": socket(PF_CAN, SOCK_RAW) failed") +
                                " (is the kernel built with CAN support?)");
  }
  const auto fail = [fd](const std::string& why) {
    const StartResult r = StartResult::failure(errno_text(why));
    close(fd);
    return r;
  };
  const unsigned ifindex = if_nametoindex(config_.interface.c_str());
  if (ifindex == 0) return fail(where + ": no such interface");

  std::array<can_filter, 4> filters{exact_filter(config_.lvdt_id, config_.extended_ids)};
  std::size_t n_filters = 1;
  if (config_.use_feedback) filters[n_filters++] = exact_filter(config_.feedback_id, config_.extended_ids);
  if (config_.use_demand) filters[n_filters++] = exact_filter(config_.demand_id, config_.extended_ids);
  if (config_.use_load_cell) filters[n_filters++] = exact_filter(config_.load_cell_id, config_.extended_ids);
  const socklen_t filter_bytes = static_cast<socklen_t>(sizeof(can_filter) * n_filters);
  const can_err_mask_t err_mask = kSubscribedErrors;
  if (setsockopt(fd, SOL_CAN_RAW, CAN_RAW_FILTER, filters.data(), filter_bytes) != 0 ||
      setsockopt(fd, SOL_CAN_RAW, CAN_RAW_ERR_FILTER, &err_mask, sizeof err_mask) != 0) {
    return fail(where + ": setsockopt failed");
  }
  sockaddr_can addr{};
  addr.can_family = AF_CAN;
  addr.can_ifindex = static_cast<int>(ifindex);
  if (bind(fd, reinterpret_cast<const sockaddr*>(&addr), sizeof addr) != 0) {
    return fail(where + ": bind failed");
  }
  return start_on(fd);
}

StartResult SocketCanBackend::start_on(int fd) {
  if (fd_ >= 0) {
    close(fd);
    return StartResult::failure("can: already started");
  }
  const auto timeout_us =
      std::chrono::duration_cast<std::chrono::microseconds>(config_.receive_timeout).count();
  const timeval tv{static_cast<time_t>(timeout_us / 1'000'000),
                   static_cast<suseconds_t>(timeout_us % 1'000'000)};
  if (setsockopt(fd, SOL_SOCKET, SO_RCVTIMEO, &tv, sizeof tv) != 0) {
    const StartResult r = StartResult::failure(errno_text("can: setsockopt(SO_RCVTIMEO) failed"));
    close(fd);
    return r;
  }
  fd_ = fd;
  // recv() returns at least every receive_timeout; a frame's decoding takes microseconds.
  thread_.set_max_silence(config_.receive_timeout + IoThread::kBeatSlice);
  thread_.start("mrd-can-rx", [this] { run(); });
  return StartResult::success();
}

void SocketCanBackend::stop() {
  thread_.stop();
  if (fd_ >= 0) close(fd_);
  fd_ = -1;
}

std::optional<CurrentReading> SocketCanBackend::measured() { return feedback_.take(); }

std::optional<bool> SocketCanBackend::feedback_driver_fault() const {
  const int f = feedback_fault_.load(std::memory_order_relaxed);
  if (f < 0) return std::nullopt;
  return f == 1;
}

bool SocketCanBackend::tx_allowed() const {
  return clock_.now().count() >= tx_allowed_from_.load(std::memory_order_relaxed);
}

IoStatus SocketCanBackend::write_setpoint(double amps) {
  const auto encoded = encode_command(
      config_.command_id, {amps, enable_.load(std::memory_order_relaxed), tx_counter_});
  if (encoded.status != EncodeStatus::kOk) return IoStatus::kInvalidArgument;
  if (fd_ < 0) return IoStatus::kNotConnected;
  if (!tx_allowed()) {
    counters_.bump(CanEvent::kTxInhibited);
    return IoStatus::kTxInhibited;
  }
  can_frame frame{};
  frame.can_id = wire_id(encoded.frame.id, config_.extended_ids);
  frame.len = static_cast<std::uint8_t>(kFrameLength);
  std::memcpy(frame.data, encoded.frame.data.data(), kFrameLength);
  if (send(fd_, &frame, sizeof frame, MSG_DONTWAIT) != static_cast<ssize_t>(sizeof frame)) {
    last_send_errno_.store(errno, std::memory_order_relaxed);
    counters_.bump(CanEvent::kTxErrors);
    return IoStatus::kIoError;
  }
  last_send_errno_.store(0, std::memory_order_relaxed);
  // The receiver expects +1 per frame it sees, so only a sent frame advances the counter.
  tx_counter_ = static_cast<std::uint8_t>((tx_counter_ + 1) & 0x0F);
  counters_.bump(CanEvent::kFramesSent);
  return IoStatus::kOk;
}

std::optional<std::string> SocketCanBackend::link_problem(bool lvdt, bool feedback) const {
  const CanCounters c = counters();
  std::vector<std::string> parts;
  const auto count = [](std::uint64_t n, const char* one, const char* many) {
    return std::to_string(n) + " " + (n == 1 ? one : many);
  };
  char id[16];
  if (lvdt && c[CanEvent::kLvdtFrames] == 0) {
    std::snprintf(id, sizeof id, "0x%X", config_.lvdt_id);
    parts.push_back(std::string("no LVDT frame (id ") + id + ") received");
  }
  if (feedback && c[CanEvent::kFeedbackFrames] == 0) {
    std::snprintf(id, sizeof id, "0x%X", config_.feedback_id);
    parts.push_back(std::string("no current feedback frame (id ") + id + ") received");
  }
  if (!tx_allowed())
    parts.push_back("sends held back after bus-off (" + count(c[CanEvent::kBusOff], "time", "times") + ", restarted " +
                    std::to_string(c[CanEvent::kRestarted]) + ")");
  if (const int error = last_send_errno_.load(std::memory_order_relaxed); error != 0)
    parts.push_back(count(c[CanEvent::kTxErrors], "failed send", "failed sends") + " (last: " + std::strerror(error) + ")");
  if (parts.empty()) return std::nullopt;
  if (c[CanEvent::kErrorFrames] > 0) parts.push_back(count(c[CanEvent::kErrorFrames], "error frame", "error frames"));
  std::string text = config_.interface + ":";
  for (std::size_t i = 0; i < parts.size(); ++i) text += (i ? ", " : " ") + parts[i];
  return text;
}

void SocketCanBackend::run() {
  can_frame frame{};
  while (!thread_.stop_requested()) {
    thread_.beat();
    const ssize_t n = recv(fd_, &frame, sizeof frame, 0);
    if (n == static_cast<ssize_t>(sizeof frame)) on_frame(frame);
    // n < 0: SO_RCVTIMEO expired (EAGAIN) or an interrupted call; loop to check for stop.
  }
}

void SocketCanBackend::on_frame(const can_frame& frame) {
  const Timestamp now = clock_.now();
  if ((frame.can_id & CAN_ERR_FLAG) != 0) {
    counters_.bump(CanEvent::kErrorFrames);
    const CanErrorEvent e = classify_error_frame(frame);
    if (e.has(kErrBusOff)) counters_.bump(CanEvent::kBusOff);
    if (e.has(kErrRestarted)) counters_.bump(CanEvent::kRestarted);
    if (e.has(kErrPassive) || e.has(kErrWarning) || e.has(kErrOverflow)) {
      counters_.bump(CanEvent::kControllerProblems);
    }
    bus_off_.on_error(e, now);
    tx_allowed_from_.store(bus_off_.tx_allowed_from().count(), std::memory_order_relaxed);
    return;
  }
  const bool extended = (frame.can_id & CAN_EFF_FLAG) != 0;
  const std::uint32_t id = frame.can_id & (extended ? CAN_EFF_MASK : CAN_SFF_MASK);
  const std::span<const std::uint8_t> data(frame.data, std::min<std::size_t>(frame.len, 8));
  if (extended != config_.extended_ids) {
    counters_.bump(CanEvent::kUnexpectedFrames);
  } else if (id == config_.lvdt_id) {
    const auto d = decode_lvdt(id, data, config_.lvdt_id, &lvdt_.counter);
    on_sample_frame(lvdt_, d.status, d.value.displacement, d.value.sensor_fault);
  } else if (config_.use_feedback && id == config_.feedback_id) {
    on_feedback(data, id);
  } else if (config_.use_demand && id == config_.demand_id) {
    // DemandInvalid is the outer controller's own "sensor fault".
    const auto d = decode_demand(id, data, config_.demand_id, &demand_.counter);
    on_sample_frame(demand_, d.status, d.value.demand, d.value.invalid);
  } else if (config_.use_load_cell && id == config_.load_cell_id) {
    // LoadCellInvalid is the amplifier's "sensor fault".
    const auto d = decode_load_cell(id, data, config_.load_cell_id, &load_cell_.counter);
    on_sample_frame(load_cell_, d.status, d.value.force, d.value.invalid);
  } else {
    counters_.bump(CanEvent::kUnexpectedFrames);
  }
  // Any frame from the bus, ours or not, proves our controller is back on it (BusOffPolicy).
  bus_off_.on_good_frame(now);
  tx_allowed_from_.store(bus_off_.tx_allowed_from().count(), std::memory_order_relaxed);
}

bool SocketCanBackend::count_rejection(DecodeStatus status) {
  switch (status) {
    case DecodeStatus::kOk: return false;
    case DecodeStatus::kOutOfSequence: counters_.bump(CanEvent::kSequenceGaps); return false;
    case DecodeStatus::kWrongDlc: counters_.bump(CanEvent::kWrongDlc); return true;
    case DecodeStatus::kBadChecksum: counters_.bump(CanEvent::kBadChecksum); return true;
    case DecodeStatus::kRepeatedCounter: counters_.bump(CanEvent::kRepeatedCounter); return true;
    case DecodeStatus::kWrongId: counters_.bump(CanEvent::kUnexpectedFrames); return true;
  }
  return true;
}

void SocketCanBackend::on_sample_frame(FrameChannel& channel, DecodeStatus status, double value, bool fault) {
  const bool rejected = count_rejection(status);
  // A repeated counter is a stale copy, not a new sample; other rejections are passed on as
  // corrupted samples so the loop sees the sender misbehave.
  if (status == DecodeStatus::kRepeatedCounter) return;
  Sample s{value, clock_.now(), channel.samples.next_sequence(), kSampleValid};
  if (rejected) s = {0.0, s.timestamp, s.sequence, kSampleCorrupted};
  if (status == DecodeStatus::kOutOfSequence) s.flags |= kSampleSequenceGap;
  if (!rejected && fault) s.flags |= kSampleSensorFault;
  if (!rejected) counters_.bump(channel.good_frames);
  if (!channel.samples.push(s)) counters_.bump(CanEvent::kSamplesDropped);
}

void SocketCanBackend::on_feedback(std::span<const std::uint8_t> data, std::uint32_t id) {
  const auto d = decode_feedback(id, data, config_.feedback_id, &feedback_counter_);
  if (count_rejection(d.status)) return;
  counters_.bump(CanEvent::kFeedbackFrames);
  feedback_.publish({d.value.measured, clock_.now()});
  feedback_fault_.store(d.value.driver_fault ? 1 : 0, std::memory_order_relaxed);
}

}  // namespace mrd::hal::can
