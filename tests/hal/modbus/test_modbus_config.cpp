#include "hal/modbus/modbus_config.hpp"

#include <gtest/gtest.h>

namespace {

using namespace std::chrono_literals;
using namespace mrd::hal::modbus;

TEST(ModbusConfig, DefaultsAreValidForBothTransports) {
  ModbusConfig c;
  EXPECT_TRUE(c.validate().ok()) << c.validate().to_string();
  c.transport = Transport::kRtu;
  EXPECT_TRUE(c.validate().ok()) << c.validate().to_string();
}

TEST(ModbusConfig, EachBadFieldIsReportedWithItsPath) {
  ModbusConfig c;
  c.transport = Transport::kRtu;
  c.rtu = {"", 0, 'X', 9, 3};
  c.slave_id = 0;
  c.response_timeout = 0us;
  c.byte_timeout = -1us;
  c.poll_period = 0us;
  c.reconnect_min = 100ms;
  c.reconnect_max = 10ms;
  c.registers.lvdt_address = 65535;  // an int32 needs two words
  c.registers.lvdt.scale = 0.0;
  c.registers.has_current_feedback = true;
  c.registers.current_feedback_address = -1;
  const auto r = c.validate();
  for (const char* field :
       {"rtu.device", "rtu.baud", "rtu.parity", "rtu.data_bits", "rtu.stop_bits", "slave_id",
        "response_timeout", "byte_timeout", "poll_period", "reconnect_max",
        "registers.lvdt_address", "registers.lvdt.scale", "registers.current_feedback_address"}) {
    EXPECT_TRUE(r.mentions(field)) << field << "\n" << r.to_string();
  }
}

TEST(ModbusConfig, TheDemandRegisterIsCheckedOnlyWhenTheDemandIsRead) {
  ModbusConfig c;
  c.registers.demand_address = 65535;  // its int32 needs two words
  c.registers.demand.scale = 0.0;
  EXPECT_TRUE(c.validate().ok()) << c.validate().to_string();
  c.registers.has_demand = true;
  const auto r = c.validate();
  EXPECT_TRUE(r.mentions("registers.demand_address")) << r.to_string();
  EXPECT_TRUE(r.mentions("registers.demand.scale")) << r.to_string();
  c.registers = RegisterMap{};
  c.registers.has_demand = true;
  EXPECT_TRUE(c.validate().ok()) << c.validate().to_string();
}

TEST(ModbusConfig, TcpChecksHostPortAndGatewayUnitId) {
  ModbusConfig c;
  c.tcp = {"", 70000};
  c.slave_id = 255;  // allowed over TCP only
  const auto r = c.validate();
  EXPECT_TRUE(r.mentions("tcp.host"));
  EXPECT_TRUE(r.mentions("tcp.port"));
  EXPECT_FALSE(r.mentions("slave_id"));
  c.transport = Transport::kRtu;
  EXPECT_TRUE(c.validate().mentions("slave_id"));
}

}  // namespace
