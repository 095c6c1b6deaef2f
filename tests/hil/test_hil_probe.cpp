// Commissioning against the simulated rig: mrd-plant serves the LVDT and the coil driver over
// Modbus TCP on 127.0.0.1 (the Table 4 sine), and mrd-controller --probe reads them with the
// driver held off. The verdict is OK, the readings are decoded in millimetres within the sine's
// +-40 mm (negative ones too), the current reads 0 A, and the plant took no setpoint write.
#include <gtest/gtest.h>
#include <signal.h>

#include <chrono>
#include <fstream>
#include <regex>
#include <string>

#include "tests/hil/child_process.hpp"
#include "tests/support/test_files.hpp"

namespace {

using mrd::test::ChildProcess;
using namespace std::chrono_literals;

TEST(HilProbe, ReadsTheSimulatedRigOverModbusTcpWithTheDriverHeldOff) {
  const mrd::test::TestDirectory dir("mrd_hil_probe");
  const auto controller_config = dir / "controller.toml";
  const std::string controller_toml =
      "[backends]\nlvdt = \"modbus\"\ndriver = \"modbus\"\nlines = \"mock\"\n"
      "[modbus]\npoll_period = 0.002\nresponse_timeout = 0.1\n"
      "[modbus.registers]\nhas_current_feedback = true\n";
  std::ofstream(controller_config) << controller_toml;
  std::ofstream(dir / "plant.toml") << "[plant]\ncontroller_config = \"" << controller_config.string()
                                    << "\"\n[profile]\nkind = \"sine\"\namplitude = 0.040\nfrequency = 0.5\n";
  ChildProcess plant({MRD_PLANT_BINARY, "--config", (dir / "plant.toml").string(), "--port", "0"});
  const auto port = plant.wait_for_line(std::regex(R"(modbus tcp [0-9.]+:(\d+))"), 10s);
  ASSERT_TRUE(port) << plant.output();
  ASSERT_TRUE(plant.wait_for_line(std::regex("mrd-plant: ready"), 10s)) << plant.output();
  std::ofstream(controller_config) << controller_toml << "[modbus.tcp]\nport = " << (*port)[1] << "\n";

  ChildProcess probe({MRD_CONTROLLER_BINARY, "--probe", "--config", controller_config.string()});
  const auto code = probe.wait_exit(20s);
  plant.signal(SIGTERM);
  ASSERT_TRUE(plant.wait_exit(20s));
  // The plant's server counts the setpoint writes it took: none.
  EXPECT_TRUE(std::regex_search(plant.output(), std::regex(R"(modbus server: connections=1 requests=\d+ answered=\d+ .*setpoints=0 )")))
      << plant.output();
  ASSERT_TRUE(code) << probe.output();
  const std::string& out = probe.output();
  EXPECT_EQ(*code, 0) << out << "--- plant\n" << plant.output();
  EXPECT_NE(out.find("probe: OK"), std::string::npos) << out;
  std::smatch m;
  ASSERT_TRUE(std::regex_search(out, m, std::regex(R"(lvdt: \d+ samples in 100 polls, (\d+) usable, range (-?[0-9.]+)\.\.(-?[0-9.]+) mm)")))
      << out;
  EXPECT_GE(std::stoi(m[1]), 20);  // the plant answers every poll of its 2 ms period
  EXPECT_GE(std::stod(m[2]), -40.1);
  EXPECT_LE(std::stod(m[3]), 40.1);
  EXPECT_TRUE(std::regex_search(out, std::regex(R"(current: \d+ readings, range -?0\.0[0-9]*\.\.-?0\.0[0-9]* A)"))) << out;
  EXPECT_TRUE(std::regex_search(out, std::regex(R"(  t  0\.010 s  lvdt +-?[0-9]+\.[0-9]{4} mm|  t  0\.010 s  lvdt +none)"))) << out;
}

// The commissioning mistake the probe is for: the controller reads the plant's LVDT with the
// words swapped (low_first where the rig writes high_first). The readings come, but decode far
// outside the stroke: the probe names the range and what to check, and exits 2 (readings wrong),
// not 3 (the bus): the link itself is fine.
TEST(HilProbe, SwappedWordsAreWrongReadingsAndExitTwo) {
  const mrd::test::TestDirectory dir("mrd_hil_probe_words");
  const auto plant_side = dir / "rig.toml";
  const std::string rig_toml =
      "[backends]\nlvdt = \"modbus\"\ndriver = \"modbus\"\nlines = \"mock\"\n"
      "[modbus]\npoll_period = 0.002\nresponse_timeout = 0.1\n";
  std::ofstream(plant_side) << rig_toml;
  std::ofstream(dir / "plant.toml") << "[plant]\ncontroller_config = \"" << plant_side.string()
                                    << "\"\n[profile]\nkind = \"sine\"\namplitude = 0.040\nfrequency = 5\n";
  ChildProcess plant({MRD_PLANT_BINARY, "--config", (dir / "plant.toml").string(), "--port", "0"});
  const auto port = plant.wait_for_line(std::regex(R"(modbus tcp [0-9.]+:(\d+))"), 10s);
  ASSERT_TRUE(port) << plant.output();
  ASSERT_TRUE(plant.wait_for_line(std::regex("mrd-plant: ready"), 10s)) << plant.output();
  const auto controller_config = dir / "controller.toml";
  std::ofstream(controller_config) << rig_toml << "[modbus.tcp]\nport = " << (*port)[1]
                                   << "\n[modbus.registers.lvdt]\nword_order = \"low_first\"\n";

  ChildProcess probe({MRD_CONTROLLER_BINARY, "--probe", "--config", controller_config.string()});
  const auto code = probe.wait_exit(20s);
  plant.signal(SIGTERM);
  ASSERT_TRUE(plant.wait_exit(20s));
  ASSERT_TRUE(code) << probe.output();
  const std::string& out = probe.output();
  EXPECT_EQ(*code, 2) << out << "--- plant\n" << plant.output();
  EXPECT_NE(out.find("outside safety.displacement_min..max"), std::string::npos) << out;
  EXPECT_NE(out.find("word order"), std::string::npos) << out;
  EXPECT_EQ(out.find("probe: OK"), std::string::npos) << out;
}

}  // namespace
