#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <span>
#include <string_view>

#include "common/validation_report.hpp"

namespace mrd::hal::modbus {

// Pure conversion between Modbus register words and SI values. No libmodbus here, so the
// decoder can be unit-tested and fuzzed on arbitrary words.

enum class RegisterType : std::uint8_t { kInt16, kUint16, kInt32, kUint32, kFloat32 };

// For 32-bit values: which register holds the high half. kHighFirst is the Modbus-spec "big
// endian" (ABCD); kLowFirst is the word-swapped order many PLCs use (CDAB).
enum class WordOrder : std::uint8_t { kHighFirst, kLowFirst };

// Within one register. libmodbus already hands us host-order words; kSwapped is for devices
// that put the low byte first on the wire (BADC, DCBA).
enum class ByteOrder : std::uint8_t { kNormal, kSwapped };

// SI value = raw * scale + offset, in both directions (the setpoint's scale is A per count).
struct RegisterFormat {
  RegisterType type = RegisterType::kInt32;
  WordOrder word_order = WordOrder::kHighFirst;
  ByteOrder byte_order = ByteOrder::kNormal;
  double scale = 1.0;
  double offset = 0.0;

  [[nodiscard]] ValidationReport validate() const;  // fields: "scale", "offset"
};

[[nodiscard]] constexpr std::size_t word_count(RegisterType t) {
  return (t == RegisterType::kInt16 || t == RegisterType::kUint16) ? 1 : 2;
}

enum class CodecStatus : std::uint8_t {
  kOk,
  kWrongWordCount,  // short (or long) response for this type
  kNotFinite,       // NaN/inf in a float register, or as the value to encode
  kOutOfRange,      // the value does not fit the raw type after scaling
  kBadFormat,       // zero or non-finite scale, non-finite offset
};
[[nodiscard]] std::string_view to_string(CodecStatus s);

struct DecodeResult {
  CodecStatus status = CodecStatus::kOk;
  double value = 0.0;  // SI; meaningful only when status is kOk
};
[[nodiscard]] DecodeResult decode_register(std::span<const std::uint16_t> words,
                                           const RegisterFormat& format);

struct EncodeResult {
  CodecStatus status = CodecStatus::kOk;
  std::array<std::uint16_t, 2> words{};
  std::size_t count = 0;  // words used; 0 unless status is kOk

  [[nodiscard]] std::span<const std::uint16_t> view() const { return {words.data(), count}; }
};
[[nodiscard]] EncodeResult encode_register(double value, const RegisterFormat& format);

}  // namespace mrd::hal::modbus
