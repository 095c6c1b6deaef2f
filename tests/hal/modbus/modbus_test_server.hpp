#pragma once

#include <modbus/modbus.h>

#include <atomic>
#include <cstdint>
#include <initializer_list>
#include <mutex>
#include <thread>

namespace mrd::test {

// A real libmodbus TCP server on 127.0.0.1 for back-end tests, serving one client at a time
// from its own thread. kSilent accepts connections and requests but never answers.
class ModbusTestServer {
 public:
  enum class Mode { kReply, kSilent };

  // port 0 picks a free ephemeral port; pass an old server's port() to "come back".
  explicit ModbusTestServer(Mode mode = Mode::kReply, int port = 0);
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
  void run();
  void drop_client();

  Mode mode_;
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

}  // namespace mrd::test
