#include "hal/can/can_codec.hpp"

#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <cstdint>
#include <string_view>
#include <vector>

namespace {

using namespace mrd::hal::can;

std::span<const std::uint8_t> payload(const Frame& f) { return f.data; }

TEST(Crc8SaeJ1850, MatchesTheStandardCheckValue) {
  constexpr std::string_view text = "123456789";
  std::vector<std::uint8_t> bytes(text.begin(), text.end());
  EXPECT_EQ(crc8_sae_j1850(bytes), 0x4B);
  EXPECT_EQ(crc8_sae_j1850({}), 0x00);  // init 0xFF, final XOR 0xFF
}

TEST(CanCodec, LvdtFrameRoundTripsInMetres) {
  const auto e = encode_lvdt(kDefaultLvdtId, {-0.012345, true, 9});
  ASSERT_EQ(e.status, EncodeStatus::kOk);
  EXPECT_EQ(e.frame.id, kDefaultLvdtId);
  const auto d = decode_lvdt(e.frame.id, payload(e.frame), kDefaultLvdtId, nullptr);
  ASSERT_EQ(d.status, DecodeStatus::kOk);
  EXPECT_NEAR(d.value.displacement, -0.012345, 1e-12);
  EXPECT_TRUE(d.value.sensor_fault);
  EXPECT_EQ(d.value.counter, 9);
  // Little-endian um on the wire: -12345 = 0xFFFFCFC7.
  EXPECT_EQ(e.frame.data[0], 0xC7);
  EXPECT_EQ(e.frame.data[3], 0xFF);
}

TEST(CanCodec, CurrentFramesRoundTripInAmps) {
  const auto cmd = encode_command(kDefaultCommandId, {1.2344, true, 15});
  ASSERT_EQ(cmd.status, EncodeStatus::kOk);
  const auto dc = decode_command(cmd.frame.id, payload(cmd.frame), kDefaultCommandId, nullptr);
  ASSERT_EQ(dc.status, DecodeStatus::kOk);
  EXPECT_DOUBLE_EQ(dc.value.setpoint, 1.234);  // rounded to 1 mA
  EXPECT_TRUE(dc.value.enable);
  EXPECT_EQ(dc.value.counter, 15);

  const auto fb = encode_feedback(kDefaultFeedbackId, {-0.5, true, 3});
  const auto df = decode_feedback(fb.frame.id, payload(fb.frame), kDefaultFeedbackId, nullptr);
  ASSERT_EQ(df.status, DecodeStatus::kOk);
  EXPECT_DOUBLE_EQ(df.value.measured, -0.5);
  EXPECT_TRUE(df.value.driver_fault);
}

TEST(CanCodec, EncodeRefusesWhatTheSignalCannotCarry) {
  EXPECT_EQ(encode_command(kDefaultCommandId, {40.0, false, 0}).status, EncodeStatus::kOutOfRange);
  EXPECT_EQ(encode_command(kDefaultCommandId, {std::nan(""), false, 0}).status,
            EncodeStatus::kNotFinite);
  EXPECT_EQ(encode_lvdt(kDefaultLvdtId, {3000.0, false, 0}).status, EncodeStatus::kOutOfRange);
}

TEST(CanCodec, RejectsWrongIdDlcAndChecksum) {
  const auto e = encode_lvdt(kDefaultLvdtId, {0.001, false, 1});
  EXPECT_EQ(decode_lvdt(0x111, payload(e.frame), kDefaultLvdtId, nullptr).status,
            DecodeStatus::kWrongId);
  EXPECT_EQ(decode_lvdt(kDefaultLvdtId, payload(e.frame).first(7), kDefaultLvdtId, nullptr).status,
            DecodeStatus::kWrongDlc);
  std::array<std::uint8_t, 9> long_frame{};
  EXPECT_EQ(decode_lvdt(kDefaultLvdtId, long_frame, kDefaultLvdtId, nullptr).status,
            DecodeStatus::kWrongDlc);
  EXPECT_EQ(decode_lvdt(kDefaultLvdtId, {}, kDefaultLvdtId, nullptr).status,
            DecodeStatus::kWrongDlc);
  // Every single-bit error in any byte is caught by the CRC.
  for (std::size_t byte = 0; byte < kFrameLength; ++byte) {
    for (int bit = 0; bit < 8; ++bit) {
      Frame bad = e.frame;
      bad.data[byte] ^= static_cast<std::uint8_t>(1u << bit);
      EXPECT_EQ(decode_lvdt(kDefaultLvdtId, payload(bad), kDefaultLvdtId, nullptr).status,
                DecodeStatus::kBadChecksum)
          << "byte " << byte << " bit " << bit;
    }
  }
}

TEST(CanCodec, RollingCounterFlagsRepeatsAndGapsAndWraps) {
  RollingCounterCheck check;
  const auto frame = [](std::uint8_t counter) {
    return encode_command(kDefaultCommandId, {0.1, true, counter}).frame;
  };
  auto status = [&](std::uint8_t counter) {
    const Frame f = frame(counter);
    return decode_command(f.id, payload(f), kDefaultCommandId, &check).status;
  };
  EXPECT_EQ(status(14), DecodeStatus::kOk);  // the first frame sets the phase
  EXPECT_EQ(status(15), DecodeStatus::kOk);
  EXPECT_EQ(status(0), DecodeStatus::kOk);   // wraps modulo 16
  EXPECT_EQ(status(0), DecodeStatus::kRepeatedCounter);
  EXPECT_EQ(status(1), DecodeStatus::kOk);   // a repeat does not move the phase
  EXPECT_EQ(status(4), DecodeStatus::kOutOfSequence);
  EXPECT_EQ(status(5), DecodeStatus::kOk);   // resynchronised after a gap
  Frame corrupt = frame(6);
  corrupt.data[0] ^= 1;
  EXPECT_EQ(decode_command(corrupt.id, payload(corrupt), kDefaultCommandId, &check).status,
            DecodeStatus::kBadChecksum);
  EXPECT_EQ(status(6), DecodeStatus::kOk);  // a corrupt frame does not move the phase either
  check.reset();
  EXPECT_EQ(status(11), DecodeStatus::kOk);
}

TEST(CanCodec, ArbitraryBytesNeverCrashAndDecodeOnlyWithAValidCrc) {
  std::uint32_t state = 7;
  auto next = [&state] {
    state = state * 1664525u + 1013904223u;
    return static_cast<std::uint8_t>(state >> 24);
  };
  RollingCounterCheck check;
  int decoded = 0;
  for (int i = 0; i < 20000; ++i) {
    std::array<std::uint8_t, 12> bytes{};
    for (auto& b : bytes) b = next();
    const std::size_t len = next() % 13;
    if (i % 4 == 0 && len >= kFrameLength) {  // some with a valid CRC, to reach the counter
      bytes[7] = crc8_sae_j1850(std::span(bytes).first(7));
    }
    const auto d = decode_lvdt(kDefaultLvdtId, std::span(bytes).first(len), kDefaultLvdtId, &check);
    if (carries_values(d.status)) {
      ++decoded;
      EXPECT_TRUE(std::isfinite(d.value.displacement));
      EXPECT_LE(d.value.counter, 15);
    }
  }
  EXPECT_GT(decoded, 0);
}

}  // namespace
