#pragma once

#include <modbus/modbus.h>

#include <atomic>
#include <cstdint>
#include <functional>
#include <initializer_list>
#include <mutex>
#include <span>
#include <thread>
#include <vector>

#include "hal/modbus/modbus_config.hpp"

namespace mrd::test {

// A real libmodbus TCP server on 127.0.0.1 for back-end tests, serving one client at a time
// from its own thread. kSilent accepts connections and requests but never answers. A forging
// server answers each request with whatever bytes its Forge returns (bad responses on purpose).
class ModbusTestServer {
 public:
  enum class Mode { kReply, kSilent, kForge };
  // The raw TCP response to one request ADU (MBAP header + PDU); empty sends nothing.
  using Forge = std::function<std::vector<std::uint8_t>(std::span<const std::uint8_t> request)>;

  // port 0 picks a free ephemeral port; pass an old server's port() to "come back".
  explicit ModbusTestServer(Mode mode = Mode::kReply, int port = 0);
  explicit ModbusTestServer(Forge forge);
  ~ModbusTestServer();
  ModbusTestServer(const ModbusTestServer&) = delete;
  ModbusTestServer& operator=(const ModbusTestServer&) = delete;

  [[nodiscard]] bool listening() const { return listen_fd_ >= 0; }
  [[nodiscard]] int port() const { return port_; }
  [[nodiscard]] int connections() const { return connections_.load(); }

  void set_input_registers(int address, std::initializer_list<std::uint16_t> words);
  void set_holding_registers(int address, std::initializer_list<std::uint16_t> words);
  [[nodiscard]] std::uint16_t holding_register(int address) const;

  static constexpr int kRegisters = 64;

 private:
  void listen_on(int port);
  void run();
  void drop_client();

  Mode mode_;
  Forge forge_;
  modbus_t* ctx_ = nullptr;
  modbus_mapping_t* map_ = nullptr;
  int listen_fd_ = -1;
  int client_fd_ = -1;
  int port_ = 0;
  std::atomic<int> connections_{0};
  std::atomic<bool> stop_{false};
  mutable std::mutex map_mutex_;
  std::thread thread_;
};

// Where the back-end tests keep their registers, and the client config they use against a test
// server on `port`: short timeouts and back-off, LVDT int32 (high word first, 1 um per count) at
// kLvdtAddress, setpoint int16 (1 mA per count) at kSetpointAddress.
inline constexpr int kLvdtAddress = 10;
inline constexpr int kSetpointAddress = 20;
inline constexpr int kFeedbackAddress = 30;
hal::modbus::ModbusConfig client_config(int port);

// A TCP response to `request` carrying `pdu`: the request's transaction and unit ids, a
// correct length field. For forging replies that are wrong only where a test wants them wrong.
std::vector<std::uint8_t> tcp_response(std::span<const std::uint8_t> request,
                                       std::initializer_list<std::uint8_t> pdu);

}  // namespace mrd::test
