#include "hal/modbus/register_codec.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <limits>
#include <vector>

namespace {

using namespace mrd::hal::modbus;

RegisterFormat format(RegisterType type, WordOrder wo = WordOrder::kHighFirst,
                      ByteOrder bo = ByteOrder::kNormal, double scale = 1.0, double offset = 0.0) {
  return {type, wo, bo, scale, offset};
}

double decoded(std::vector<std::uint16_t> words, const RegisterFormat& f) {
  const auto r = decode_register(words, f);
  EXPECT_EQ(r.status, CodecStatus::kOk) << to_string(r.status);
  return r.value;
}

TEST(RegisterCodec, DecodesSixteenBitTypes) {
  EXPECT_EQ(decoded({0xFFFF}, format(RegisterType::kInt16)), -1.0);
  EXPECT_EQ(decoded({0xFFFF}, format(RegisterType::kUint16)), 65535.0);
  EXPECT_EQ(decoded({0x8000}, format(RegisterType::kInt16)), -32768.0);
  EXPECT_EQ(decoded({0x0201}, format(RegisterType::kUint16, WordOrder::kHighFirst,
                                     ByteOrder::kSwapped)),
            0x0102);
}

TEST(RegisterCodec, DecodesAllFourByteAndWordOrders) {
  // 0x12345678 as ABCD, CDAB, BADC, DCBA.
  EXPECT_EQ(decoded({0x1234, 0x5678}, format(RegisterType::kUint32)), 0x12345678);
  EXPECT_EQ(decoded({0x5678, 0x1234}, format(RegisterType::kUint32, WordOrder::kLowFirst)),
            0x12345678);
  EXPECT_EQ(decoded({0x3412, 0x7856},
                    format(RegisterType::kUint32, WordOrder::kHighFirst, ByteOrder::kSwapped)),
            0x12345678);
  EXPECT_EQ(decoded({0x7856, 0x3412},
                    format(RegisterType::kUint32, WordOrder::kLowFirst, ByteOrder::kSwapped)),
            0x12345678);
  EXPECT_EQ(decoded({0xFFFF, 0xFFFE}, format(RegisterType::kInt32)), -2.0);
}

TEST(RegisterCodec, DecodesFloatAndAppliesScaleAndOffset) {
  // 1.5f = 0x3FC00000
  EXPECT_EQ(decoded({0x3FC0, 0x0000}, format(RegisterType::kFloat32)), 1.5);
  EXPECT_EQ(decoded({0x0000, 0x3FC0}, format(RegisterType::kFloat32, WordOrder::kLowFirst)), 1.5);
  // A 1 um/count LVDT with a -25 mm zero: 12345 counts -> 12.345 mm - 25 mm.
  EXPECT_NEAR(decoded({0x0000, 12345}, format(RegisterType::kInt32, WordOrder::kHighFirst,
                                              ByteOrder::kNormal, 1e-6, -0.025)),
              -0.012655, 1e-12);
}

// Found by fuzz_register_codec (docs/RELIABILITY.md): a float register holding -0 is the value
// 0, and encoding it gives +0's words, which decode to the same value.
TEST(RegisterCodec, NegativeZeroFloatIsZeroAndRoundTripsByValue) {
  const RegisterFormat f = format(RegisterType::kFloat32, WordOrder::kHighFirst, ByteOrder::kSwapped);
  const std::vector<std::uint16_t> negative_zero{0x0080, 0x0000};  // 0x80000000 byte-swapped
  const auto d = decode_register(negative_zero, f);
  ASSERT_EQ(d.status, CodecStatus::kOk);
  EXPECT_EQ(d.value, 0.0);
  const auto e = encode_register(d.value, f);
  ASSERT_EQ(e.status, CodecStatus::kOk);
  EXPECT_EQ(decode_register(e.view(), f).value, 0.0);
}

TEST(RegisterCodec, ShortLongAndNonFiniteInputsGiveAStatus) {
  const std::vector<std::uint16_t> one{1};
  const std::vector<std::uint16_t> three{1, 2, 3};
  EXPECT_EQ(decode_register(one, format(RegisterType::kInt32)).status,
            CodecStatus::kWrongWordCount);
  EXPECT_EQ(decode_register({}, format(RegisterType::kInt16)).status,
            CodecStatus::kWrongWordCount);
  EXPECT_EQ(decode_register(three, format(RegisterType::kFloat32)).status,
            CodecStatus::kWrongWordCount);
  const std::vector<std::uint16_t> nan{0x7FC0, 0x0000};
  const std::vector<std::uint16_t> inf{0x7F80, 0x0000};
  EXPECT_EQ(decode_register(nan, format(RegisterType::kFloat32)).status, CodecStatus::kNotFinite);
  EXPECT_EQ(decode_register(inf, format(RegisterType::kFloat32)).status, CodecStatus::kNotFinite);
  EXPECT_EQ(decode_register(one, format(RegisterType::kInt16, WordOrder::kHighFirst,
                                        ByteOrder::kNormal, 0.0))
                .status,
            CodecStatus::kBadFormat);
}

TEST(RegisterCodec, EncodeRoundsAndRoundTripsEveryType) {
  const RegisterFormat milliamps =
      format(RegisterType::kUint16, WordOrder::kHighFirst, ByteOrder::kNormal, 1e-3);
  const auto e = encode_register(1.2344, milliamps);
  ASSERT_EQ(e.status, CodecStatus::kOk);
  ASSERT_EQ(e.count, 1u);
  EXPECT_EQ(e.words[0], 1234);

  for (auto type : {RegisterType::kInt16, RegisterType::kUint16, RegisterType::kInt32,
                    RegisterType::kUint32, RegisterType::kFloat32}) {
    for (auto wo : {WordOrder::kHighFirst, WordOrder::kLowFirst}) {
      for (auto bo : {ByteOrder::kNormal, ByteOrder::kSwapped}) {
        const RegisterFormat f = format(type, wo, bo, 0.5, 3.0);
        const auto enc = encode_register(100.0, f);
        ASSERT_EQ(enc.status, CodecStatus::kOk);
        EXPECT_EQ(enc.count, word_count(type));
        EXPECT_DOUBLE_EQ(decoded({enc.view().begin(), enc.view().end()}, f), 100.0);
      }
    }
  }
}

TEST(RegisterCodec, EncodeRejectsWhatTheRegisterCannotHold) {
  EXPECT_EQ(encode_register(-1.0, format(RegisterType::kUint16)).status, CodecStatus::kOutOfRange);
  EXPECT_EQ(encode_register(65535.4, format(RegisterType::kUint16)).status, CodecStatus::kOk);
  EXPECT_EQ(encode_register(65535.6, format(RegisterType::kUint16)).status,
            CodecStatus::kOutOfRange);
  EXPECT_EQ(encode_register(40000.0, format(RegisterType::kInt16)).status,
            CodecStatus::kOutOfRange);
  EXPECT_EQ(encode_register(1e40, format(RegisterType::kFloat32)).status,
            CodecStatus::kOutOfRange);
  EXPECT_EQ(encode_register(std::nan(""), format(RegisterType::kInt32)).status,
            CodecStatus::kNotFinite);
  EXPECT_EQ(encode_register(std::numeric_limits<double>::infinity(), format(RegisterType::kFloat32))
                .status,
            CodecStatus::kNotFinite);
  EXPECT_EQ(encode_register(1.0, format(RegisterType::kInt32, WordOrder::kHighFirst,
                                        ByteOrder::kNormal, std::nan("")))
                .status,
            CodecStatus::kBadFormat);
}

TEST(RegisterCodec, ArbitraryWordsNeverCrashAndGiveAFiniteValueOrAStatus) {
  std::uint32_t state = 12345;
  auto next = [&state] {
    state = state * 1664525u + 1013904223u;
    return static_cast<std::uint16_t>(state >> 16);
  };
  for (int i = 0; i < 20000; ++i) {
    const std::vector<std::uint16_t> words{next(), next()};
    const auto r = decode_register(words, format(RegisterType::kFloat32, WordOrder::kLowFirst,
                                                 ByteOrder::kSwapped, 1e-3));
    if (r.status == CodecStatus::kOk) EXPECT_TRUE(std::isfinite(r.value));
    else EXPECT_EQ(r.status, CodecStatus::kNotFinite);
  }
}

TEST(RegisterFormat, ValidateNamesTheBadFields) {
  RegisterFormat f;
  EXPECT_TRUE(f.validate().ok());
  f.scale = 0.0;
  f.offset = std::nan("");
  const auto report = f.validate();
  EXPECT_TRUE(report.mentions("scale"));
  EXPECT_TRUE(report.mentions("offset"));
}

}  // namespace
