#include "hal/modbus/register_codec.hpp"

#include <bit>
#include <cmath>
#include <limits>

namespace mrd::hal::modbus {

namespace {

bool format_ok(const RegisterFormat& f) {
  return std::isfinite(f.scale) && f.scale != 0.0 && std::isfinite(f.offset);
}

std::uint16_t apply_byte_order(std::uint16_t w, ByteOrder order) {
  return order == ByteOrder::kSwapped ? static_cast<std::uint16_t>((w << 8) | (w >> 8)) : w;
}

// Raw two's-complement/IEEE bits of the value, as the device means them.
std::uint32_t assemble(std::span<const std::uint16_t> words, const RegisterFormat& f) {
  const std::uint16_t first = apply_byte_order(words[0], f.byte_order);
  if (words.size() == 1) return first;
  const std::uint16_t second = apply_byte_order(words[1], f.byte_order);
  const bool high_first = f.word_order == WordOrder::kHighFirst;
  const std::uint32_t hi = high_first ? first : second;
  const std::uint32_t lo = high_first ? second : first;
  return (hi << 16) | lo;
}

double raw_value(std::uint32_t bits, RegisterType type) {
  switch (type) {
    case RegisterType::kInt16: return static_cast<std::int16_t>(static_cast<std::uint16_t>(bits));
    case RegisterType::kUint16: return static_cast<std::uint16_t>(bits);
    case RegisterType::kInt32: return static_cast<std::int32_t>(bits);
    case RegisterType::kUint32: return bits;
    case RegisterType::kFloat32: return std::bit_cast<float>(bits);
  }
  return 0.0;
}

struct RawRange {
  double lo;
  double hi;
};
RawRange raw_range(RegisterType type) {
  switch (type) {
    case RegisterType::kInt16: return {-32768.0, 32767.0};
    case RegisterType::kUint16: return {0.0, 65535.0};
    case RegisterType::kInt32: return {-2147483648.0, 2147483647.0};
    case RegisterType::kUint32: return {0.0, 4294967295.0};
    case RegisterType::kFloat32: {
      const double max = std::numeric_limits<float>::max();
      return {-max, max};
    }
  }
  return {0.0, 0.0};
}

std::uint32_t raw_bits(double raw, RegisterType type) {
  switch (type) {
    case RegisterType::kInt16: return static_cast<std::uint16_t>(static_cast<std::int16_t>(raw));
    case RegisterType::kUint16: return static_cast<std::uint16_t>(raw);
    case RegisterType::kInt32: return static_cast<std::uint32_t>(static_cast<std::int32_t>(raw));
    case RegisterType::kUint32: return static_cast<std::uint32_t>(raw);
    case RegisterType::kFloat32: return std::bit_cast<std::uint32_t>(static_cast<float>(raw));
  }
  return 0;
}

}  // namespace

ValidationReport RegisterFormat::validate() const {
  ValidationReport r;
  r.check(std::isfinite(scale) && scale != 0.0, "scale", "must be finite and non-zero");
  r.check(std::isfinite(offset), "offset", "must be finite");
  return r;
}

std::string_view to_string(CodecStatus s) {
  switch (s) {
    case CodecStatus::kOk: return "ok";
    case CodecStatus::kWrongWordCount: return "wrong register count";
    case CodecStatus::kNotFinite: return "value not finite";
    case CodecStatus::kOutOfRange: return "value out of the register's range";
    case CodecStatus::kBadFormat: return "bad register format";
  }
  return "unknown";
}

DecodeResult decode_register(std::span<const std::uint16_t> words, const RegisterFormat& format) {
  if (!format_ok(format)) return {CodecStatus::kBadFormat, 0.0};
  if (words.size() != word_count(format.type)) return {CodecStatus::kWrongWordCount, 0.0};
  const double raw = raw_value(assemble(words, format), format.type);
  const double value = raw * format.scale + format.offset;
  if (!std::isfinite(value)) return {CodecStatus::kNotFinite, 0.0};
  return {CodecStatus::kOk, value};
}

EncodeResult encode_register(double value, const RegisterFormat& format) {
  if (!format_ok(format)) return {CodecStatus::kBadFormat, {}, 0};
  if (!std::isfinite(value)) return {CodecStatus::kNotFinite, {}, 0};
  double raw = (value - format.offset) / format.scale;
  if (format.type != RegisterType::kFloat32) raw = std::round(raw);
  const RawRange range = raw_range(format.type);
  if (!(raw >= range.lo && raw <= range.hi)) return {CodecStatus::kOutOfRange, {}, 0};

  const std::uint32_t bits = raw_bits(raw, format.type);
  EncodeResult out;
  out.count = word_count(format.type);
  if (out.count == 1) {
    out.words[0] = apply_byte_order(static_cast<std::uint16_t>(bits), format.byte_order);
    return out;
  }
  const auto hi = apply_byte_order(static_cast<std::uint16_t>(bits >> 16), format.byte_order);
  const auto lo = apply_byte_order(static_cast<std::uint16_t>(bits), format.byte_order);
  const bool high_first = format.word_order == WordOrder::kHighFirst;
  out.words = {high_first ? hi : lo, high_first ? lo : hi};
  return out;
}

}  // namespace mrd::hal::modbus
