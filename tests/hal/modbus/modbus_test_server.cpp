#include "tests/hal/modbus/modbus_test_server.hpp"

#include <netinet/in.h>
#include <poll.h>
#include <sys/socket.h>
#include <unistd.h>

#include <algorithm>
#include <array>

namespace mrd::test {

ModbusTestServer::ModbusTestServer(Mode mode, int port) : mode_(mode) { listen_on(port); }

// The forge is in place before listen_on() starts the thread that calls it.
ModbusTestServer::ModbusTestServer(Forge forge) : mode_(Mode::kForge), forge_(std::move(forge)) {
  listen_on(0);
}

void ModbusTestServer::listen_on(int port) {
  ctx_ = modbus_new_tcp("127.0.0.1", port);
  map_ = modbus_mapping_new(0, 0, kRegisters, kRegisters);
  if (ctx_ == nullptr || map_ == nullptr) return;
  modbus_set_indication_timeout(ctx_, 0, 200'000);
  listen_fd_ = modbus_tcp_listen(ctx_, 1);
  if (listen_fd_ < 0) return;
  sockaddr_in addr{};
  socklen_t len = sizeof addr;
  getsockname(listen_fd_, reinterpret_cast<sockaddr*>(&addr), &len);
  port_ = ntohs(addr.sin_port);
  thread_ = std::thread([this] { run(); });
}

ModbusTestServer::~ModbusTestServer() {
  stop_ = true;
  if (thread_.joinable()) thread_.join();
  drop_client();
  if (listen_fd_ >= 0) close(listen_fd_);
  if (map_ != nullptr) modbus_mapping_free(map_);
  if (ctx_ != nullptr) modbus_free(ctx_);
}

void ModbusTestServer::set_input_registers(int address, std::initializer_list<std::uint16_t> words) {
  const std::lock_guard lock(map_mutex_);
  for (auto w : words) map_->tab_input_registers[address++] = w;
}

void ModbusTestServer::set_holding_registers(int address,
                                             std::initializer_list<std::uint16_t> words) {
  const std::lock_guard lock(map_mutex_);
  for (auto w : words) map_->tab_registers[address++] = w;
}

std::uint16_t ModbusTestServer::holding_register(int address) const {
  const std::lock_guard lock(map_mutex_);
  return map_->tab_registers[address];
}

void ModbusTestServer::drop_client() {
  if (client_fd_ < 0) return;
  close(client_fd_);
  client_fd_ = -1;
  modbus_set_socket(ctx_, -1);
}

void ModbusTestServer::run() {
  std::array<std::uint8_t, MODBUS_TCP_MAX_ADU_LENGTH> query{};
  while (!stop_) {
    std::array<pollfd, 2> fds{{{listen_fd_, POLLIN, 0}, {client_fd_, POLLIN, 0}}};
    if (poll(fds.data(), client_fd_ >= 0 ? 2 : 1, 20) <= 0) continue;
    if ((fds[0].revents & POLLIN) != 0) {
      drop_client();  // one client at a time: a reconnecting client replaces the old link
      int fd = listen_fd_;
      client_fd_ = modbus_tcp_accept(ctx_, &fd);
      if (client_fd_ >= 0) ++connections_;
      continue;
    }
    if (client_fd_ < 0 || fds[1].revents == 0) continue;
    const int rc = modbus_receive(ctx_, query.data());
    if (rc < 0) {
      drop_client();
    } else if (rc > 0 && mode_ == Mode::kReply) {
      const std::lock_guard lock(map_mutex_);
      modbus_reply(ctx_, query.data(), rc, map_);
    } else if (rc > 0 && mode_ == Mode::kForge) {
      const auto bytes = forge_(std::span(query).first(static_cast<std::size_t>(rc)));
      if (!bytes.empty()) (void)send(client_fd_, bytes.data(), bytes.size(), MSG_NOSIGNAL);
    }
  }
}

hal::modbus::ModbusConfig client_config(int port) {
  using namespace std::chrono_literals;
  hal::modbus::ModbusConfig c;
  c.tcp.port = port;
  c.response_timeout = 100ms;
  c.poll_period = 1ms;
  c.reconnect_min = 5ms;
  c.reconnect_max = 40ms;
  c.registers.lvdt_address = kLvdtAddress;
  c.registers.setpoint_address = kSetpointAddress;
  return c;
}

std::vector<std::uint8_t> tcp_response(std::span<const std::uint8_t> request,
                                       std::initializer_list<std::uint8_t> pdu) {
  const auto length = static_cast<std::uint16_t>(pdu.size() + 1);  // unit id + PDU
  std::vector<std::uint8_t> out(7 + pdu.size());
  out[0] = request[0];  // transaction id
  out[1] = request[1];
  out[4] = static_cast<std::uint8_t>(length >> 8);
  out[5] = static_cast<std::uint8_t>(length & 0xFF);
  out[6] = request[6];  // unit id
  std::copy(pdu.begin(), pdu.end(), out.begin() + 7);
  return out;
}

}  // namespace mrd::test
