#include "hal/can/can_codec.hpp"

#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <cstdint>
#include <string_view>
#include <utility>
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

// The check table of AUTOSAR's CRC library specification for its 8-bit SAE J1850 routine.
TEST(Crc8SaeJ1850, MatchesTheAutosarCheckTable) {
  const std::vector<std::pair<std::vector<std::uint8_t>, std::uint8_t>> table{
      {{0x00, 0x00, 0x00, 0x00}, 0x59},
      {{0xF2, 0x01, 0x83}, 0x37},
      {{0x0F, 0xAA, 0x00, 0x55}, 0x79},
      {{0x00, 0xFF, 0x55, 0x11}, 0xB8},
      {{0x33, 0x22, 0x55, 0xAA, 0xBB, 0xCC, 0xDD, 0xEE, 0xFF}, 0xCB},
      {{0x92, 0x6B, 0x55}, 0x8C},
      {{0xFF, 0xFF, 0xFF, 0xFF}, 0x74},
  };
  for (const auto& [bytes, crc] : table) EXPECT_EQ(crc8_sae_j1850(bytes), crc) << int{crc};
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

TEST(CanCodec, ForceDemandFrameRoundTripsInNewtons) {
  const auto e = encode_demand(kDefaultDemandId, {-31415.93, false, 7});
  ASSERT_EQ(e.status, EncodeStatus::kOk);
  const auto d = decode_demand(e.frame.id, payload(e.frame), kDefaultDemandId, nullptr);
  ASSERT_EQ(d.status, DecodeStatus::kOk);
  EXPECT_NEAR(d.value.demand, -31415.9, 1e-9);  // rounded to 0.1 N
  EXPECT_FALSE(d.value.invalid);
  EXPECT_EQ(d.value.counter, 7);
  // Little-endian 0.1 N on the wire: -314159 = 0xFFFB34D1.
  EXPECT_EQ(e.frame.data[0], 0xD1);
  EXPECT_EQ(e.frame.data[1], 0x34);
  EXPECT_EQ(e.frame.data[2], 0xFB);
  EXPECT_EQ(e.frame.data[3], 0xFF);
  EXPECT_EQ(encode_demand(kDefaultDemandId, {1.0, true, 0}).frame.data[4], 1) << "the invalid flag";
  EXPECT_EQ(encode_demand(kDefaultDemandId, {std::nan(""), false, 0}).status, EncodeStatus::kNotFinite);
  EXPECT_EQ(encode_demand(kDefaultDemandId, {3e8, false, 0}).status, EncodeStatus::kOutOfRange);
}

TEST(CanCodec, ABadDemandFrameIsNeverUsed) {
  RollingCounterCheck counter;
  const auto first = encode_demand(kDefaultDemandId, {1000.0, false, 3}).frame;
  ASSERT_EQ(decode_demand(kDefaultDemandId, payload(first), kDefaultDemandId, &counter).status, DecodeStatus::kOk);
  EXPECT_EQ(decode_demand(kDefaultDemandId, payload(first), kDefaultDemandId, &counter).status,
            DecodeStatus::kRepeatedCounter)
      << "the same frame again is a stale demand";
  const auto next = encode_demand(kDefaultDemandId, {1100.0, false, 4}).frame;
  EXPECT_EQ(decode_demand(kDefaultDemandId, payload(next).first(6), kDefaultDemandId, &counter).status,
            DecodeStatus::kWrongDlc);
  Frame flipped = next;
  flipped.data[2] ^= 0x10;
  EXPECT_EQ(decode_demand(kDefaultDemandId, payload(flipped), kDefaultDemandId, &counter).status,
            DecodeStatus::kBadChecksum);
  EXPECT_EQ(decode_demand(kDefaultLvdtId, payload(next), kDefaultDemandId, &counter).status, DecodeStatus::kWrongId);
  const auto skipped = encode_demand(kDefaultDemandId, {1200.0, false, 6}).frame;
  EXPECT_EQ(decode_demand(kDefaultDemandId, payload(skipped), kDefaultDemandId, &counter).status,
            DecodeStatus::kOutOfSequence)
      << "frame 4 never got through: counter 6 after 3 is a gap (its value is still good)";
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

// A frame whose checksum byte is anything but the CRC of bytes 0-6 is rejected, for every
// message: no value is carried out of it, and it does not take the rolling counter, so the
// sender's next good frame is still in sequence.
TEST(CanCodec, EveryWrongChecksumIsRejectedForEveryMessage) {
  const auto check = [](const char* message, auto encode, auto decode, std::uint32_t id) {
    RollingCounterCheck counter;
    const Frame first = encode(id, 4).frame;
    ASSERT_EQ(decode(id, payload(first), id, &counter).status, DecodeStatus::kOk) << message;
    const Frame good = encode(id, 5).frame;
    int rejected = 0;
    for (int checksum = 0; checksum < 256; ++checksum) {
      if (checksum == good.data[7]) continue;
      Frame bad = good;
      bad.data[7] = static_cast<std::uint8_t>(checksum);
      const auto d = decode(id, payload(bad), id, &counter);
      EXPECT_EQ(d.status, DecodeStatus::kBadChecksum) << message << " checksum " << checksum;
      EXPECT_FALSE(carries_values(d.status));
      EXPECT_EQ(d.value.counter, 0) << "a rejected frame carries nothing out";
      rejected += d.status == DecodeStatus::kBadChecksum ? 1 : 0;
    }
    EXPECT_EQ(rejected, 255) << message;
    const auto after = decode(id, payload(good), id, &counter);
    EXPECT_EQ(after.status, DecodeStatus::kOk) << message << ": the bad frames moved the counter";
    EXPECT_EQ(after.value.counter, 5) << message;
  };
  check("LVDT", [](std::uint32_t id, std::uint8_t n) { return encode_lvdt(id, {0.0123, true, n}); },
        decode_lvdt, kDefaultLvdtId);
  check("command", [](std::uint32_t id, std::uint8_t n) { return encode_command(id, {1.25, true, n}); },
        decode_command, kDefaultCommandId);
  check("feedback", [](std::uint32_t id, std::uint8_t n) { return encode_feedback(id, {-0.75, true, n}); },
        decode_feedback, kDefaultFeedbackId);
  check("demand", [](std::uint32_t id, std::uint8_t n) { return encode_demand(id, {-12345.6, true, n}); },
        decode_demand, kDefaultDemandId);
}

// What a CRC-8 adds over a weaker checksum (an XOR or a sum of the bytes catches every single-bit
// error too): every two-bit error in the 64-bit frame, and every burst of up to 8 bits, is caught.
// Bits are numbered in the order the CRC reads them, most significant bit of byte 0 first: a
// burst that crosses a byte boundary in any other numbering is not one to the CRC.
TEST(CanCodec, EveryTwoBitErrorAndEveryShortBurstIsCaught) {
  const Frame good = encode_feedback(kDefaultFeedbackId, {0.321, false, 7}).frame;
  const auto flipped = [&good](std::uint64_t mask) {  // bit 63 of mask: the first bit read
    Frame f = good;
    for (std::size_t i = 0; i < kFrameLength; ++i) f.data[i] ^= static_cast<std::uint8_t>(mask >> (56 - 8 * i));
    return decode_feedback(f.id, payload(f), kDefaultFeedbackId, nullptr).status;
  };
  int missed = 0;
  for (int a = 0; a < 64; ++a) {
    for (int b = a + 1; b < 64; ++b) {
      missed += flipped((std::uint64_t{1} << a) | (std::uint64_t{1} << b)) != DecodeStatus::kBadChecksum;
    }
    for (std::uint64_t burst = 1; burst < 256 && a + 8 <= 64; burst += 2) {  // lowest bit at a
      missed += flipped(burst << a) != DecodeStatus::kBadChecksum;
    }
  }
  EXPECT_EQ(missed, 0);
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
  int bad_checksum = 0;
  for (int i = 0; i < 20000; ++i) {
    std::array<std::uint8_t, 12> bytes{};
    for (auto& b : bytes) b = next();
    const std::size_t len = next() % 13;
    if (i % 4 == 0 && len >= kFrameLength) {  // some with a valid CRC, to reach the counter
      bytes[7] = crc8_sae_j1850(std::span(bytes).first(7));
    }
    const auto d = decode_lvdt(kDefaultLvdtId, std::span(bytes).first(len), kDefaultLvdtId, &check);
    // The verdict, from the frame's own bytes: DLC first, then the checksum.
    if (len != kFrameLength) {
      ASSERT_EQ(d.status, DecodeStatus::kWrongDlc) << i;
      continue;
    }
    if (bytes[7] != crc8_sae_j1850(std::span(bytes).first(7))) {
      ASSERT_EQ(d.status, DecodeStatus::kBadChecksum) << i;
      ++bad_checksum;
      continue;
    }
    if (carries_values(d.status)) {
      ++decoded;
      // The DBC's layout, read here by hand: int32 LE um, the fault bit, the counter nibble.
      const auto um = static_cast<std::int32_t>(bytes[0] | bytes[1] << 8 | bytes[2] << 16 |
                                                static_cast<std::uint32_t>(bytes[3]) << 24);
      ASSERT_DOUBLE_EQ(d.value.displacement, um * 1e-6) << i;
      ASSERT_EQ(d.value.sensor_fault, (bytes[4] & 1) != 0) << i;
      ASSERT_EQ(d.value.counter, bytes[6] & 0x0F) << i;
    }
  }
  // 1 in 13 frames has 8 bytes; a quarter of those carry a valid CRC.
  EXPECT_GT(decoded, 250);
  EXPECT_GT(bad_checksum, 1000);
}

}  // namespace
