#include "hal/gpio/gpiod_lines.hpp"

#include <gtest/gtest.h>

namespace {

using mrd::hal::IoStatus;
using namespace mrd::hal::gpio;

TEST(GpioConfig, DefaultsAreValidAndLabelsNameTheRole) {
  GpioConfig c;
  EXPECT_TRUE(c.validate().ok()) << c.validate().to_string();
  EXPECT_EQ(c.consumer("enable"), "mrd-enable");
  EXPECT_EQ(c.consumer("heartbeat"), "mrd-heartbeat");
}

TEST(GpioConfig, ReportsEachBadFieldWithItsPath) {
  GpioConfig c;
  c.chip = "";
  c.enable.offset = -1;
  c.fault.offset = 3;
  c.heartbeat.offset = 3;
  c.consumer_prefix = std::string(30, 'x');
  const auto r = c.validate();
  for (const char* field : {"chip", "enable.offset", "heartbeat.offset", "consumer_prefix"}) {
    EXPECT_TRUE(r.mentions(field)) << field << "\n" << r.to_string();
  }
  c = GpioConfig{};
  c.fault.offset = c.enable.offset;
  EXPECT_TRUE(c.validate().mentions("fault.offset"));
}

TEST(GpiodLines, MissingChipIsAClearErrorAndTheLinesStayInert) {
  GpioConfig c;
  c.chip = "mrd-no-such-chip";
  GpiodLines lines(c);
  const auto result = lines.start();
  ASSERT_FALSE(result.ok);
  EXPECT_NE(result.error.find("mrd-no-such-chip"), std::string::npos) << result.error;
  EXPECT_NE(result.error.find("cannot open chip"), std::string::npos) << result.error;
  // No exception escapes, and the fault line reads as unknown (the caller treats it as a fault).
  EXPECT_EQ(lines.set_enable(true), IoStatus::kNotConnected);
  EXPECT_EQ(lines.toggle_heartbeat(), IoStatus::kNotConnected);
  EXPECT_FALSE(lines.driver_fault().has_value());
}

TEST(GpiodLines, BadConfigIsRefusedBeforeOpeningAnything) {
  GpioConfig c;
  c.heartbeat.offset = c.enable.offset;
  GpiodLines lines(c);
  const auto result = lines.start();
  ASSERT_FALSE(result.ok);
  EXPECT_NE(result.error.find("heartbeat.offset"), std::string::npos) << result.error;
}

}  // namespace
