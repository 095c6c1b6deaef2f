// Forged and out-of-sequence CAN frames end to end (docs/RELIABILITY.md): frames go through
// SocketCanBackend's receive thread as they would from the bus, over a socketpair, since the
// build machine's kernel has no CAN. The documented reaction: a frame with a bad checksum or a
// wrong DLC becomes a corrupted (unusable) sample and is counted; a repeated counter is a stale
// copy, counted and never a new sample; a counter jump is counted and its value used, flagged;
// other ids are counted as unexpected and never decoded, however many.
#include <sys/socket.h>
#include <unistd.h>

#include <gtest/gtest.h>

#include <cstring>

#include "hal/can/socketcan_backend.hpp"
#include "tests/hal/test_wait.hpp"

namespace {

using mrd::hal::MonotonicClock;
using mrd::test::wait_for;
using namespace mrd::hal::can;

// The back end with `config`, its receive thread fed through a socketpair.
class ForgedBusBase : public ::testing::Test {
 protected:
  explicit ForgedBusBase(SocketCanConfig config) : backend_(std::move(config), clock_) {}
  void SetUp() override {
    int fds[2];
    ASSERT_EQ(socketpair(AF_UNIX, SOCK_DGRAM | SOCK_CLOEXEC, 0, fds), 0);
    bus_ = fds[1];
    const auto started = backend_.start_on(fds[0]);
    ASSERT_TRUE(started.ok) << started.error;
  }
  void TearDown() override {
    backend_.stop();
    if (bus_ >= 0) close(bus_);
  }

  void send_frame(canid_t id, std::span<const std::uint8_t> data) {
    can_frame frame{};
    frame.can_id = id;
    frame.len = static_cast<std::uint8_t>(data.size());
    std::memcpy(frame.data, data.data(), data.size());
    ASSERT_EQ(send(bus_, &frame, sizeof frame, 0), static_cast<ssize_t>(sizeof frame));
  }
  // Waits until the receive thread has counted `n` of `event`.
  bool counted(CanEvent event, std::uint64_t n) {
    return wait_for([&] { return backend_.counters()[event] == n; });
  }

  MonotonicClock clock_;
  SocketCanBackend backend_;
  int bus_ = -1;
};

class ForgedBus : public ForgedBusBase {
 protected:
  ForgedBus() : ForgedBusBase(SocketCanConfig{}) {}
  void send_lvdt(double metres, std::uint8_t counter) {
    send_frame(kDefaultLvdtId, encode_lvdt(kDefaultLvdtId, {metres, false, counter}).frame.data);
  }
};

TEST_F(ForgedBus, BadChecksumWrongDlcAndRepeatedCounterAreNeverUsed) {
  send_lvdt(0.001, 0);
  ASSERT_TRUE(counted(CanEvent::kLvdtFrames, 1));
  auto s = backend_.lvdt().latest();
  ASSERT_TRUE(s && s->usable());
  EXPECT_DOUBLE_EQ(s->value, 0.001);

  auto forged = encode_lvdt(kDefaultLvdtId, {0.5, false, 1}).frame;
  forged.data[7] ^= 0x01;  // checksum off by one bit
  send_frame(kDefaultLvdtId, forged.data);
  ASSERT_TRUE(counted(CanEvent::kBadChecksum, 1));
  s = backend_.lvdt().latest();
  ASSERT_TRUE(s);
  EXPECT_FALSE(s->usable());
  EXPECT_TRUE(s->flags & mrd::hal::kSampleCorrupted);

  const auto good = encode_lvdt(kDefaultLvdtId, {0.5, false, 1}).frame;
  send_frame(kDefaultLvdtId, std::span(good.data).first(5));  // DLC 5
  ASSERT_TRUE(counted(CanEvent::kWrongDlc, 1));
  s = backend_.lvdt().latest();
  ASSERT_TRUE(s);
  EXPECT_FALSE(s->usable());

  send_lvdt(0.002, 0);  // the last good frame's counter again: a replayed copy
  ASSERT_TRUE(counted(CanEvent::kRepeatedCounter, 1));
  EXPECT_FALSE(backend_.lvdt().latest().has_value());

  send_lvdt(0.003, 5);  // counter jumps 0 -> 5: frames were lost, the value is good
  ASSERT_TRUE(counted(CanEvent::kSequenceGaps, 1));
  s = backend_.lvdt().latest();
  ASSERT_TRUE(s && s->usable());
  EXPECT_TRUE(s->flags & mrd::hal::kSampleSequenceGap);
  EXPECT_DOUBLE_EQ(s->value, 0.003);
  EXPECT_EQ(backend_.counters()[CanEvent::kLvdtFrames], 2u);

  auto feedback = encode_feedback(kDefaultFeedbackId, {1.5, false, 0}).frame;
  feedback.data[0] ^= 0x80;  // a flipped bit in the value
  send_frame(kDefaultFeedbackId, feedback.data);
  ASSERT_TRUE(counted(CanEvent::kBadChecksum, 2));
  EXPECT_FALSE(backend_.measured().has_value());
  EXPECT_EQ(backend_.counters()[CanEvent::kFeedbackFrames], 0u);
}

// The link's problem line names the interface, each expected frame that never came, and failed
// sends with the system's reason; it clears once the frames come and nothing fails.
TEST_F(ForgedBus, TheLinkProblemNamesMissingFramesAndFailedSendsWithTheirReason) {
  const auto problem = backend_.link_problem(true, true);
  ASSERT_TRUE(problem);
  EXPECT_EQ(*problem, "can0: no LVDT frame (id 0x110) received, no current feedback frame (id 0x211) received");
  EXPECT_EQ(backend_.link_problem(false, false), std::nullopt);  // a link that carries neither
  send_lvdt(0.001, 0);
  ASSERT_TRUE(counted(CanEvent::kLvdtFrames, 1));
  EXPECT_EQ(backend_.link_problem(true, false), std::nullopt);
  close(bus_);  // the peer gone: every send fails
  bus_ = -1;
  EXPECT_EQ(backend_.write_setpoint(1.0), mrd::hal::IoStatus::kIoError);
  EXPECT_EQ(backend_.link_problem(true, false), "can0: 1 failed send (last: Connection refused)");
}

TEST_F(ForgedBus, AFloodOfUnexpectedIdsIsCountedAndTheLvdtStillGetsThrough) {
  constexpr int kFlood = 20000;
  constexpr int kLvdtEvery = 1000;
  const std::array<std::uint8_t, 8> junk{0xDE, 0xAD, 0xBE, 0xEF, 0, 0, 0, 0};
  std::uint8_t counter = 0;
  for (int i = 0; i < kFlood; ++i) {
    // Standard ids next to ours, and an extended frame carrying our LVDT id.
    send_frame(i % 2 == 0 ? kDefaultLvdtId + 1 : (kDefaultLvdtId | CAN_EFF_FLAG), junk);
    if (i % kLvdtEvery == kLvdtEvery - 1) {
      send_lvdt(1e-6 * i, counter);
      counter = static_cast<std::uint8_t>((counter + 1) & 0x0F);
    }
  }
  ASSERT_TRUE(counted(CanEvent::kLvdtFrames, kFlood / kLvdtEvery));
  ASSERT_TRUE(counted(CanEvent::kUnexpectedFrames, kFlood));
  const auto c = backend_.counters();
  EXPECT_EQ(c[CanEvent::kBadChecksum] + c[CanEvent::kWrongDlc] + c[CanEvent::kSequenceGaps], 0u);
  const auto s = backend_.lvdt().latest();
  ASSERT_TRUE(s && s->usable());
  EXPECT_DOUBLE_EQ(s->value, 1e-6 * (kFlood - 1));
}

// The Force_Demand frame through the same receive thread: newtons inside, and the LVDT's
// reaction to bad frames, with DemandInvalid as the sender's own fault flag.
class ForgedDemandBus : public ForgedBusBase {
 protected:
  static SocketCanConfig demand_config() {
    SocketCanConfig c;
    c.use_demand = true;
    return c;
  }
  ForgedDemandBus() : ForgedBusBase(demand_config()) {}
  void send_demand_frame(std::span<const std::uint8_t> data) { send_frame(kDefaultDemandId, data); }
};

TEST_F(ForgedDemandBus, DemandFramesBecomeSamplesInNewtonsAndBadOnesAreNeverUsed) {
  // 0x120 with bytes 0-3 = -12345 counts of 0.1 N, written by hand (little-endian), flags 0,
  // counter 0, and the CRC from the codec's checked CRC routine.
  std::array<std::uint8_t, 8> hand{0xC7, 0xCF, 0xFF, 0xFF, 0x00, 0x00, 0x00, 0x00};
  hand[7] = crc8_sae_j1850(std::span(hand).first(7));
  send_demand_frame(hand);
  ASSERT_TRUE(counted(CanEvent::kDemandFrames, 1));
  auto s = backend_.demand().latest();
  ASSERT_TRUE(s && s->usable());
  EXPECT_DOUBLE_EQ(s->value, -1234.5);
  EXPECT_EQ(s->sequence, 1u);
  EXPECT_FALSE(backend_.lvdt().latest().has_value()) << "a demand is not a displacement";

  auto forged = encode_demand(kDefaultDemandId, {500.0, false, 1}).frame;
  forged.data[2] ^= 0x10;  // a flipped bit in the value
  send_demand_frame(forged.data);
  ASSERT_TRUE(counted(CanEvent::kBadChecksum, 1));
  s = backend_.demand().latest();
  ASSERT_TRUE(s);
  EXPECT_FALSE(s->usable());
  EXPECT_TRUE(s->flags & mrd::hal::kSampleCorrupted);

  const auto good = encode_demand(kDefaultDemandId, {500.0, false, 1}).frame;
  send_demand_frame(std::span(good.data).first(6));  // DLC 6
  ASSERT_TRUE(counted(CanEvent::kWrongDlc, 1));
  s = backend_.demand().latest();
  ASSERT_TRUE(s);
  EXPECT_TRUE(s->flags & mrd::hal::kSampleCorrupted);

  send_demand_frame(encode_demand(kDefaultDemandId, {700.0, false, 0}).frame.data);  // counter 0 again
  ASSERT_TRUE(counted(CanEvent::kRepeatedCounter, 1));
  EXPECT_FALSE(backend_.demand().latest().has_value());

  send_demand_frame(encode_demand(kDefaultDemandId, {800.0, false, 3}).frame.data);  // 0 -> 3: lost frames
  ASSERT_TRUE(counted(CanEvent::kSequenceGaps, 1));
  s = backend_.demand().latest();
  ASSERT_TRUE(s && s->usable());
  EXPECT_TRUE(s->flags & mrd::hal::kSampleSequenceGap);
  EXPECT_DOUBLE_EQ(s->value, 800.0);

  send_demand_frame(encode_demand(kDefaultDemandId, {900.0, true, 4}).frame.data);  // DemandInvalid
  ASSERT_TRUE(counted(CanEvent::kDemandFrames, 3));
  s = backend_.demand().latest();
  ASSERT_TRUE(s);
  EXPECT_FALSE(s->usable());
  EXPECT_TRUE(s->flags & mrd::hal::kSampleSensorFault);
  EXPECT_FALSE(s->flags & mrd::hal::kSampleCorrupted);
  EXPECT_EQ(s->sequence, 5u) << "one sample each but for the repeated counter";
}

TEST_F(ForgedBus, WithoutUseDemandTheDemandFrameIsUnexpected) {
  send_frame(kDefaultDemandId, encode_demand(kDefaultDemandId, {100.0, false, 0}).frame.data);
  ASSERT_TRUE(counted(CanEvent::kUnexpectedFrames, 1));
  EXPECT_FALSE(backend_.demand().latest().has_value());
  EXPECT_EQ(backend_.counters()[CanEvent::kDemandFrames], 0u);
}

// The Load_Cell frame (force mode's optional load cell) next to the demand on one bus: each
// id to its own channel, and the demand's reaction to bad frames, LoadCellInvalid as the
// amplifier's own fault flag.
class ForgedLoadCellBus : public ForgedBusBase {
 protected:
  static SocketCanConfig load_cell_config() {
    SocketCanConfig c;
    c.use_demand = true;
    c.use_load_cell = true;
    return c;
  }
  ForgedLoadCellBus() : ForgedBusBase(load_cell_config()) {}
  void send_load_cell_frame(std::span<const std::uint8_t> data) { send_frame(kDefaultLoadCellId, data); }
};

TEST_F(ForgedLoadCellBus, LoadCellFramesBecomeSamplesInNewtonsApartFromTheDemand) {
  // 0x130 with bytes 0-3 = 43210 counts of 0.1 N (0x0000A8CA, little-endian) written by hand.
  std::array<std::uint8_t, 8> hand{0xCA, 0xA8, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00};
  hand[7] = crc8_sae_j1850(std::span(hand).first(7));
  send_load_cell_frame(hand);
  send_frame(kDefaultDemandId, encode_demand(kDefaultDemandId, {-100.0, false, 0}).frame.data);
  ASSERT_TRUE(counted(CanEvent::kLoadCellFrames, 1));
  ASSERT_TRUE(counted(CanEvent::kDemandFrames, 1));
  auto s = backend_.load_cell().latest();
  ASSERT_TRUE(s && s->usable());
  EXPECT_DOUBLE_EQ(s->value, 4321.0);
  EXPECT_EQ(s->sequence, 1u);
  const auto demand = backend_.demand().latest();
  ASSERT_TRUE(demand && demand->usable());
  EXPECT_DOUBLE_EQ(demand->value, -100.0) << "the load cell is not the demand";
  EXPECT_FALSE(backend_.load_cell().latest().has_value()) << "one sample per frame";

  auto forged = encode_load_cell(kDefaultLoadCellId, {500.0, false, 1}).frame;
  forged.data[1] ^= 0x04;  // a flipped bit in the value
  send_load_cell_frame(forged.data);
  ASSERT_TRUE(counted(CanEvent::kBadChecksum, 1));
  s = backend_.load_cell().latest();
  ASSERT_TRUE(s);
  EXPECT_FALSE(s->usable());
  EXPECT_TRUE(s->flags & mrd::hal::kSampleCorrupted);

  send_load_cell_frame(encode_load_cell(kDefaultLoadCellId, {600.0, false, 0}).frame.data);  // counter 0 again
  ASSERT_TRUE(counted(CanEvent::kRepeatedCounter, 1));
  EXPECT_FALSE(backend_.load_cell().latest().has_value());

  send_load_cell_frame(encode_load_cell(kDefaultLoadCellId, {-700.0, true, 1}).frame.data);  // LoadCellInvalid
  ASSERT_TRUE(counted(CanEvent::kLoadCellFrames, 2));
  s = backend_.load_cell().latest();
  ASSERT_TRUE(s);
  EXPECT_FALSE(s->usable());
  EXPECT_TRUE(s->flags & mrd::hal::kSampleSensorFault);
  EXPECT_EQ(s->sequence, 3u) << "one sample each but for the repeated counter";
}

TEST_F(ForgedBus, WithoutUseLoadCellTheLoadCellFrameIsUnexpected) {
  send_frame(kDefaultLoadCellId, encode_load_cell(kDefaultLoadCellId, {100.0, false, 0}).frame.data);
  ASSERT_TRUE(counted(CanEvent::kUnexpectedFrames, 1));
  EXPECT_FALSE(backend_.load_cell().latest().has_value());
  EXPECT_EQ(backend_.counters()[CanEvent::kLoadCellFrames], 0u);
}

}  // namespace
