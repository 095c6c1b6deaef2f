// The power-management QoS request: the 32-bit value written as cyclictest writes it, held
// while the object lives, and a warning (never a failure) when the device cannot be opened.
#include "runtime/cpu_dma_latency.hpp"

#include <gtest/gtest.h>
#include <unistd.h>

#include <cstdint>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>

namespace {

using mrd::runtime::CpuDmaLatency;

std::string contents(const std::filesystem::path& p) {
  std::ifstream in(p, std::ios::binary);
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

TEST(CpuDmaLatency, WritesTheValueAsA32BitIntegerAndKeepsTheDeviceOpen) {
  // A regular file stands in for the device: what lands in it is what the kernel would read.
  const auto device = std::filesystem::temp_directory_path() / ("mrd_dma_latency_" + std::to_string(getpid()));
  std::ofstream(device).close();
  CpuDmaLatency qos;
  EXPECT_EQ(qos.hold(7, device.string()), "");
  EXPECT_TRUE(qos.held());
  const std::string written = contents(device);
  ASSERT_EQ(written.size(), sizeof(std::int32_t));
  std::int32_t value = -1;
  std::memcpy(&value, written.data(), sizeof value);
  EXPECT_EQ(value, 7);

  CpuDmaLatency moved = std::move(qos);  // the request moves with the descriptor
  EXPECT_TRUE(moved.held());
  EXPECT_FALSE(qos.held());  // NOLINT(bugprone-use-after-move): moved-from is empty by contract
  moved.release();
  EXPECT_FALSE(moved.held());
  std::filesystem::remove(device);
}

TEST(CpuDmaLatency, AMissingDeviceIsAWarningThatSaysWhatItCosts) {
  CpuDmaLatency qos;
  const std::string warning = qos.hold(0, "/nonexistent/cpu_dma_latency");
  EXPECT_FALSE(qos.held());
  EXPECT_NE(warning.find("cannot hold /nonexistent/cpu_dma_latency at 0 us (open: No such file or directory)"),
            std::string::npos)
      << warning;
  EXPECT_NE(warning.find("wake-up latency grows"), std::string::npos) << warning;
}

}  // namespace
