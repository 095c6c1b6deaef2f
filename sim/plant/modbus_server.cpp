#include "sim/plant/modbus_server.hpp"

#include <modbus/modbus.h>
#include <netinet/in.h>
#include <poll.h>
#include <pty.h>
#include <sys/socket.h>
#include <termios.h>
#include <unistd.h>

#include <algorithm>
#include <array>
#include <cerrno>
#include <cstring>
#include <filesystem>

#include "hal/modbus/register_codec.hpp"

namespace mrd::plant {

namespace {

using hal::modbus::CodecStatus;
using hal::modbus::RegisterKind;
using hal::modbus::RegisterType;

constexpr int kMaxClients = 8;

// Two words in one atomic: the first in the high half.
std::uint32_t pack(const hal::modbus::EncodeResult& e) {
  return e.count == 1 ? e.words[0] : (std::uint32_t{e.words[0]} << 16) | e.words[1];
}

void unpack(std::uint32_t packed, RegisterType type, std::uint16_t* out) {
  if (hal::modbus::word_count(type) == 1) {
    out[0] = static_cast<std::uint16_t>(packed);
  } else {
    out[0] = static_cast<std::uint16_t>(packed >> 16);
    out[1] = static_cast<std::uint16_t>(packed);
  }
}

int top_address(const hal::modbus::RegisterMap& r) {
  return std::max({r.lvdt_address + 2, r.setpoint_address + 2, r.current_feedback_address + 2, r.demand_address + 2,
                   r.demand_counter_address + 1});
}

}  // namespace

ModbusServer::ModbusServer(hal::modbus::ModbusConfig layout, std::string host, int port,
                           std::string rtu_link, std::uint32_t seed)
    : layout_(std::move(layout)),
      host_(std::move(host)),
      port_(port),
      rtu_link_(std::move(rtu_link)),
      rng_(seed ^ 0x5bd1e995u) {}

ModbusServer::~ModbusServer() {
  stop();
  close_all();
  if (pty_master_ >= 0) close(pty_master_);
  if (pty_slave_ >= 0) close(pty_slave_);
  if (!rtu_link_.empty() && layout_.transport == hal::modbus::Transport::kRtu) {
    std::error_code ignored;
    std::filesystem::remove(rtu_link_, ignored);
  }
  if (map_ != nullptr) modbus_mapping_free(map_);
  if (ctx_ != nullptr) modbus_free(ctx_);
}

bool ModbusServer::listen_tcp(std::string& error) {
  if (ctx_ == nullptr) {
    ctx_ = modbus_new_tcp(host_.c_str(), port_);
    if (ctx_ == nullptr) {
      error = hal::errno_text("modbus server: cannot create a TCP context for " + host_);
      return false;
    }
    modbus_set_indication_timeout(ctx_, 0, 200'000);
  }
  listen_fd_ = modbus_tcp_listen(ctx_, kMaxClients);
  if (listen_fd_ < 0) {
    error = hal::errno_text("modbus server: cannot listen on " + host_ + ":" + std::to_string(port_));
    return false;
  }
  if (port_ == 0) {
    // An ephemeral port: a restart must come back on the same one.
    sockaddr_in addr{};
    socklen_t len = sizeof addr;
    getsockname(listen_fd_, reinterpret_cast<sockaddr*>(&addr), &len);
    port_ = ntohs(addr.sin_port);
    close(listen_fd_);
    modbus_free(ctx_);
    ctx_ = nullptr;
    return listen_tcp(error);
  }
  endpoint_ = host_ + ":" + std::to_string(port_);
  return true;
}

hal::StartResult ModbusServer::start() {
  if (const auto report = layout_.validate(); !report.ok()) {
    return hal::StartResult::failure("modbus layout:\n" + report.to_string());
  }
  const int registers = std::max(top_address(layout_.registers), layout_.registers.load_cell_address + 2);
  map_ = modbus_mapping_new(0, 0, registers, registers);
  if (map_ == nullptr) return hal::StartResult::failure(hal::errno_text("modbus server: no mapping"));
  std::string error;
  if (layout_.transport == hal::modbus::Transport::kTcp) {
    if (!listen_tcp(error)) return hal::StartResult::failure(error);
  } else {
    const auto& rtu = layout_.rtu;
    // libmodbus's RTU framing on the pty master; the controller opens the slave side.
    ctx_ = modbus_new_rtu("/dev/null", rtu.baud, rtu.parity, rtu.data_bits, rtu.stop_bits);
    if (ctx_ == nullptr) return hal::StartResult::failure(hal::errno_text("modbus server: no RTU context"));
    modbus_set_slave(ctx_, layout_.slave_id);
    modbus_set_indication_timeout(ctx_, 0, 200'000);
    std::array<char, 128> name{};
    termios raw{};
    cfmakeraw(&raw);
    if (openpty(&pty_master_, &pty_slave_, name.data(), &raw, nullptr) != 0) {
      return hal::StartResult::failure(hal::errno_text("modbus server: openpty failed"));
    }
    modbus_set_socket(ctx_, pty_master_);
    const std::string link = rtu_link_.empty() ? layout_.rtu.device : rtu_link_;
    std::error_code ec;
    std::filesystem::remove(link, ec);
    std::filesystem::create_symlink(name.data(), link, ec);
    if (ec) return hal::StartResult::failure("modbus server: cannot link " + link + ": " + ec.message());
    rtu_link_ = link;
    endpoint_ = link + " -> " + name.data();
  }
  thread_.start("plant-modbus", [this] { run(); });
  return hal::StartResult::success();
}

void ModbusServer::stop() { thread_.stop(); }

void ModbusServer::close_all() {
  for (const int fd : clients_) close(fd);
  clients_.clear();
  if (listen_fd_ >= 0) close(listen_fd_);
  listen_fd_ = -1;
}

void ModbusServer::publish(const SensorReadings& readings, const ActiveFaults& faults) {
  const auto& r = layout_.registers;
  const std::optional<double>& demand = readings.demand;
  if (const auto e = encode_register(readings.lvdt, r.lvdt); e.status == CodecStatus::kOk) {
    lvdt_words_.store(pack(e), std::memory_order_relaxed);
  }
  if (const auto e = encode_register(readings.coil_current, r.current_feedback); e.status == CodecStatus::kOk) {
    feedback_words_.store(pack(e), std::memory_order_relaxed);
  }
  if (demand && !faults.has(FaultKind::kDemandStale)) {
    const double sent = faults.has(FaultKind::kDemandInvalid) ? faults.value_of(FaultKind::kDemandInvalid) : *demand;
    if (const auto e = encode_register(sent, r.demand); e.status == CodecStatus::kOk) {
      // Only this thread writes: the count +1 (16 bits, wrapping) with the new words.
      const std::uint64_t count = ((demand_state_.load(std::memory_order_relaxed) >> 32) + 1) & 0xFFFF;
      demand_state_.store((count << 32) | pack(e), std::memory_order_relaxed);
    }
  }
  stall_.store(faults.has(FaultKind::kServerStall), std::memory_order_relaxed);
  down_.store(faults.has(FaultKind::kServerRestart), std::memory_order_relaxed);
  lvdt_silent_.store(faults.has(FaultKind::kLvdtSilent), std::memory_order_relaxed);
  corrupt_.store(faults.has(FaultKind::kBadChecksum), std::memory_order_relaxed);
  loss_.store(faults.has(FaultKind::kFrameLoss) ? faults.value_of(FaultKind::kFrameLoss) / 100.0 : 0.0,
              std::memory_order_relaxed);
  delay_.store(faults.has(FaultKind::kDelay) ? faults.value_of(FaultKind::kDelay) : 0.0,
               std::memory_order_relaxed);
}

void ModbusServer::publish_load_cell(double force) {
  if (const auto e = encode_register(force, layout_.registers.load_cell); e.status == CodecStatus::kOk) {
    load_cell_words_.store(pack(e), std::memory_order_relaxed);
  }
}

ModbusServerCounters ModbusServer::counters() const {
  return {connections_.load(), requests_.load(),   answered_.load(), unanswered_.load(),
          exceptions_.load(),  setpoints_.load(), restarts_.load()};
}

void ModbusServer::fill_registers() {
  const auto& r = layout_.registers;
  std::uint16_t* lvdt = r.lvdt_kind == RegisterKind::kInput ? map_->tab_input_registers : map_->tab_registers;
  unpack(lvdt_words_.load(std::memory_order_relaxed), r.lvdt.type, lvdt + r.lvdt_address);
  std::uint16_t* fb = r.current_feedback_kind == RegisterKind::kInput ? map_->tab_input_registers
                                                                      : map_->tab_registers;
  if (r.has_current_feedback) {
    unpack(feedback_words_.load(std::memory_order_relaxed), r.current_feedback.type,
           fb + r.current_feedback_address);
  }
  if (r.has_demand) {
    std::uint16_t* table = r.demand_kind == RegisterKind::kInput ? map_->tab_input_registers : map_->tab_registers;
    const std::uint64_t state = demand_state_.load(std::memory_order_relaxed);
    unpack(static_cast<std::uint32_t>(state), r.demand.type, table + r.demand_address);
    if (r.has_demand_counter()) table[r.demand_counter_address] = static_cast<std::uint16_t>(state >> 32);
  }
  if (r.has_load_cell) {
    std::uint16_t* load_cell =
        r.load_cell_kind == RegisterKind::kInput ? map_->tab_input_registers : map_->tab_registers;
    unpack(load_cell_words_.load(std::memory_order_relaxed), r.load_cell.type, load_cell + r.load_cell_address);
  }
}

void ModbusServer::take_setpoint() {
  const auto& r = layout_.registers;
  const std::span<const std::uint16_t> words(map_->tab_registers + r.setpoint_address,
                                             hal::modbus::word_count(r.setpoint.type));
  const auto decoded = decode_register(words, r.setpoint);
  if (decoded.status != CodecStatus::kOk) return;
  setpoint_.store(decoded.value, std::memory_order_relaxed);
  setpoints_.fetch_add(1, std::memory_order_relaxed);
}

void ModbusServer::serve(int fd) {
  std::array<std::uint8_t, MODBUS_TCP_MAX_ADU_LENGTH> query{};
  modbus_set_socket(ctx_, fd);
  const int rc = modbus_receive(ctx_, query.data());
  if (rc < 0) {
    if (layout_.transport == hal::modbus::Transport::kTcp) {
      close(fd);
      clients_.erase(std::remove(clients_.begin(), clients_.end(), fd), clients_.end());
    } else {
      modbus_flush(ctx_);  // a garbled RTU frame: drop it and wait for the next
    }
    return;
  }
  if (rc == 0) return;  // for another slave
  requests_.fetch_add(1, std::memory_order_relaxed);
  const int header = modbus_get_header_length(ctx_);
  const int function = query[static_cast<std::size_t>(header)];
  const int address = (query[static_cast<std::size_t>(header) + 1] << 8) | query[static_cast<std::size_t>(header) + 2];
  const bool lvdt_read = (function == 0x03 || function == 0x04) && address == layout_.registers.lvdt_address;
  std::uniform_real_distribution<double> uniform(0.0, 1.0);
  if (stall_.load() || (lvdt_silent_.load() && lvdt_read) || uniform(rng_) < loss_.load()) {
    unanswered_.fetch_add(1, std::memory_order_relaxed);
    return;
  }
  if (const double delay = delay_.load(); delay > 0.0) {
    thread_.wait_for(std::chrono::duration_cast<std::chrono::steady_clock::duration>(
        std::chrono::duration<double>(delay)));
  }
  if (corrupt_.load()) {
    modbus_reply_exception(ctx_, query.data(), MODBUS_EXCEPTION_SLAVE_OR_SERVER_FAILURE);
    exceptions_.fetch_add(1, std::memory_order_relaxed);
    return;
  }
  fill_registers();
  modbus_reply(ctx_, query.data(), rc, map_);
  answered_.fetch_add(1, std::memory_order_relaxed);
  if (function == 0x06 || function == 0x10) take_setpoint();
}

void ModbusServer::run() {
  const bool tcp = layout_.transport == hal::modbus::Transport::kTcp;
  bool was_down = false;
  std::vector<pollfd> fds;
  while (!thread_.stop_requested()) {
    if (down_.load()) {
      // A restart: every connection goes, and nobody is listening until the window ends.
      if (!was_down) {
        close_all();
        restarts_.fetch_add(1, std::memory_order_relaxed);
        was_down = true;
      }
      thread_.wait_for(std::chrono::milliseconds{1});
      continue;
    }
    if (was_down && tcp) {
      std::string error;
      if (!listen_tcp(error)) {
        thread_.wait_for(std::chrono::milliseconds{10});
        continue;
      }
    }
    was_down = false;
    fds.clear();
    fds.push_back({tcp ? listen_fd_ : pty_master_, POLLIN, 0});
    for (const int fd : clients_) fds.push_back({fd, POLLIN, 0});
    if (poll(fds.data(), fds.size(), 10) <= 0) continue;
    if (!tcp) {
      if ((fds[0].revents & POLLIN) != 0) serve(pty_master_);
      continue;
    }
    for (std::size_t i = 1; i < fds.size(); ++i) {
      if (fds[i].revents != 0) serve(fds[i].fd);
    }
    if ((fds[0].revents & POLLIN) != 0) {
      int fd = listen_fd_;
      const int client = modbus_tcp_accept(ctx_, &fd);
      if (client >= 0) {
        if (clients_.size() >= kMaxClients) {
          close(client);
        } else {
          clients_.push_back(client);
          connections_.fetch_add(1, std::memory_order_relaxed);
        }
      }
    }
  }
}

}  // namespace mrd::plant
