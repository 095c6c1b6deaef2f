#include "hal/can/socketcan_backend.hpp"

#include <gtest/gtest.h>
#include <sys/socket.h>
#include <unistd.h>

namespace {

using mrd::hal::IoStatus;
using mrd::hal::MonotonicClock;
using namespace mrd::hal::can;

bool kernel_has_can() {
  const int fd = socket(PF_CAN, SOCK_RAW, CAN_RAW);
  if (fd < 0) return false;
  close(fd);
  return true;
}

TEST(SocketCanBackend, UnopenableBusFailsCleanlyAndStaysInert) {
  MonotonicClock clock;
  SocketCanConfig config;
  config.interface = "mrdnosuch0";
  SocketCanBackend backend(config, clock);
  const auto result = backend.start();
  ASSERT_FALSE(result.ok);
  // Either the kernel has no CAN (this build machine) or the interface does not exist.
  EXPECT_NE(result.error.find("mrdnosuch0"), std::string::npos) << result.error;
  if (!kernel_has_can()) {
    EXPECT_NE(result.error.find("socket(PF_CAN"), std::string::npos) << result.error;
  } else {
    EXPECT_NE(result.error.find("no such interface"), std::string::npos) << result.error;
  }
  EXPECT_FALSE(backend.lvdt().latest().has_value());
  EXPECT_FALSE(backend.measured().has_value());
  EXPECT_FALSE(backend.feedback_driver_fault().has_value());
  EXPECT_EQ(backend.write_setpoint(0.5), IoStatus::kNotConnected);
  EXPECT_EQ(backend.write_setpoint(100.0), IoStatus::kInvalidArgument);
  EXPECT_EQ(backend.counters()[CanEvent::kFramesSent], 0u);
  backend.stop();  // harmless when never started
}

TEST(SocketCanBackend, BadConfigIsRefusedBeforeTouchingTheKernel) {
  MonotonicClock clock;
  SocketCanConfig config;
  config.interface = "";
  config.command_id = config.lvdt_id;
  SocketCanBackend backend(config, clock);
  const auto result = backend.start();
  ASSERT_FALSE(result.ok);
  EXPECT_NE(result.error.find("interface"), std::string::npos) << result.error;
  EXPECT_NE(result.error.find("command_id"), std::string::npos) << result.error;
}

TEST(SocketCanConfig, ValidatesIdsNamesAndTimes) {
  SocketCanConfig c;
  EXPECT_TRUE(c.validate().ok()) << c.validate().to_string();
  c.interface = "a-name-that-is-too-long";
  c.lvdt_id = 0x800;  // needs 29-bit ids
  c.feedback_id = c.command_id;
  c.receive_timeout = std::chrono::milliseconds{0};
  c.bus_off_hold_off = std::chrono::milliseconds{-1};
  auto r = c.validate();
  for (const char* field :
       {"interface", "lvdt_id", "feedback_id", "receive_timeout", "bus_off_hold_off"}) {
    EXPECT_TRUE(r.mentions(field)) << field << "\n" << r.to_string();
  }
  c = SocketCanConfig{};
  c.extended_ids = true;
  c.lvdt_id = 0x18FF0010;
  EXPECT_TRUE(c.validate().ok()) << c.validate().to_string();
  c.use_feedback = false;
  c.feedback_id = c.lvdt_id;  // ignored when feedback is off
  EXPECT_TRUE(c.validate().ok()) << c.validate().to_string();
}

TEST(SocketCanConfig, TheDemandIdIsCheckedOnlyWhenTheDemandIsReceived) {
  SocketCanConfig c;
  c.demand_id = c.command_id;
  EXPECT_TRUE(c.validate().ok()) << c.validate().to_string();
  c.use_demand = true;
  EXPECT_TRUE(c.validate().mentions("demand_id")) << c.validate().to_string();
  c.demand_id = c.feedback_id;
  EXPECT_TRUE(c.validate().mentions("demand_id"));
  c.use_feedback = false;  // then the feedback's id is free
  EXPECT_TRUE(c.validate().ok()) << c.validate().to_string();
  c = SocketCanConfig{};
  c.use_demand = true;
  EXPECT_TRUE(c.validate().ok()) << "0x120 is the default and clashes with nothing";
  c.demand_id = 0x800;
  EXPECT_TRUE(c.validate().mentions("demand_id")) << "needs 29-bit ids";
}

}  // namespace
