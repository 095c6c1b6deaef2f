// The DBC is what users load into their CAN tools; this keeps it and the codec in agreement by
// decoding the codec's frames with the DBC's own signal definitions.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <fstream>
#include <map>
#include <regex>
#include <string>

#include "hal/can/can_codec.hpp"

namespace {

using namespace mrd::hal::can;

struct Signal {
  int start = 0;
  int length = 0;
  bool little_endian = true;
  bool is_signed = false;
  double factor = 1.0;
  double offset = 0.0;
};
struct Message {
  int dlc = 0;
  std::map<std::string, Signal> signals;
};

std::map<std::uint32_t, Message> load_dbc() {
  std::ifstream in(std::string(MRD_SOURCE_DIR) + "/hal/can/mrd.dbc");
  const std::regex bo(R"(^BO_ (\d+) \w+: (\d+) \w+)");
  const std::regex sg(R"(^ SG_ (\w+) : (\d+)\|(\d+)@([01])([+-]) \(([^,]+),([^)]+)\))");
  std::map<std::uint32_t, Message> messages;
  Message* current = nullptr;
  std::string line;
  std::smatch m;
  while (std::getline(in, line)) {
    if (std::regex_search(line, m, bo)) {
      current = &messages[static_cast<std::uint32_t>(std::stoul(m[1]))];
      current->dlc = std::stoi(m[2]);
    } else if (current != nullptr && std::regex_search(line, m, sg)) {
      current->signals[m[1]] = {std::stoi(m[2]), std::stoi(m[3]), m[4] == "1", m[5] == "-",
                                std::stod(m[6]), std::stod(m[7])};
    }
  }
  return messages;
}

double physical(const Frame& f, const Signal& s) {
  std::uint64_t word = 0;
  for (std::size_t i = 0; i < kFrameLength; ++i) word |= std::uint64_t{f.data[i]} << (8 * i);
  std::uint64_t raw = (word >> s.start) & ((std::uint64_t{1} << s.length) - 1);
  double value = static_cast<double>(raw);
  if (s.is_signed && (raw >> (s.length - 1)) != 0) value -= std::ldexp(1.0, s.length);
  return value * s.factor + s.offset;
}

class DbcMatchesCodec : public ::testing::Test {
 protected:
  void SetUp() override {
    dbc = load_dbc();
    ASSERT_EQ(dbc.size(), 5u) << "hal/can/mrd.dbc not found or not parsed";
    for (const auto& [id, message] : dbc) {
      EXPECT_EQ(message.dlc, static_cast<int>(kFrameLength));
      for (const auto& [name, s] : message.signals) EXPECT_TRUE(s.little_endian) << name;
      EXPECT_EQ(message.signals.at("RollingCounter").start, 48);
      EXPECT_EQ(message.signals.at("Checksum").start, 56);
    }
  }
  std::map<std::uint32_t, Message> dbc;
};

TEST_F(DbcMatchesCodec, LvdtFrame) {
  const Frame f = encode_lvdt(kDefaultLvdtId, {-0.012345, true, 9}).frame;
  const auto& sig = dbc.at(kDefaultLvdtId).signals;
  EXPECT_NEAR(physical(f, sig.at("Displacement")), -12.345, 1e-9);  // mm
  EXPECT_EQ(physical(f, sig.at("SensorFault")), 1.0);
  EXPECT_EQ(physical(f, sig.at("RollingCounter")), 9.0);
  EXPECT_EQ(physical(f, sig.at("Checksum")), f.data[7]);
}

TEST_F(DbcMatchesCodec, ForceDemandFrame) {
  const Frame f = encode_demand(kDefaultDemandId, {-31415.9, true, 14}).frame;
  const auto& sig = dbc.at(kDefaultDemandId).signals;
  EXPECT_NEAR(physical(f, sig.at("Demand")), -31415.9, 1e-6);  // N
  EXPECT_EQ(physical(f, sig.at("DemandInvalid")), 1.0);
  EXPECT_EQ(physical(f, sig.at("RollingCounter")), 14.0);
  EXPECT_EQ(physical(f, sig.at("Checksum")), f.data[7]);
}

TEST_F(DbcMatchesCodec, LoadCellFrame) {
  const Frame f = encode_load_cell(kDefaultLoadCellId, {27182.8, true, 3}).frame;
  const auto& sig = dbc.at(kDefaultLoadCellId).signals;
  EXPECT_NEAR(physical(f, sig.at("Force")), 27182.8, 1e-6);  // N
  EXPECT_EQ(physical(f, sig.at("LoadCellInvalid")), 1.0);
  EXPECT_EQ(physical(f, sig.at("RollingCounter")), 3.0);
  EXPECT_EQ(physical(f, sig.at("Checksum")), f.data[7]);
  const Frame ok = encode_load_cell(kDefaultLoadCellId, {-1234.5, false, 4}).frame;
  EXPECT_NEAR(physical(ok, sig.at("Force")), -1234.5, 1e-6);
  EXPECT_EQ(physical(ok, sig.at("LoadCellInvalid")), 0.0);
}

TEST_F(DbcMatchesCodec, CommandAndFeedbackFrames) {
  const Frame cmd = encode_command(kDefaultCommandId, {-1.5, true, 4}).frame;
  const auto& c = dbc.at(kDefaultCommandId).signals;
  EXPECT_EQ(physical(cmd, c.at("CurrentSetpoint")), -1500.0);  // mA
  EXPECT_EQ(physical(cmd, c.at("DriverEnable")), 1.0);
  EXPECT_EQ(physical(cmd, c.at("RollingCounter")), 4.0);

  const Frame fb = encode_feedback(kDefaultFeedbackId, {0.75, true, 12}).frame;
  const auto& b = dbc.at(kDefaultFeedbackId).signals;
  EXPECT_EQ(physical(fb, b.at("MeasuredCurrent")), 750.0);
  EXPECT_EQ(physical(fb, b.at("DriverFault")), 1.0);
  EXPECT_EQ(physical(fb, b.at("RollingCounter")), 12.0);
}

}  // namespace
