#include "hal/can/can_codec.hpp"

#include <cmath>
#include <limits>
#include <type_traits>

namespace mrd::hal::can {

namespace {

constexpr std::size_t kFlagByte = 2;  // current frames; the LVDT frame has its flag in byte 4
constexpr std::size_t kLvdtFlagByte = 4;
constexpr std::size_t kCounterByte = 6;
constexpr std::size_t kChecksumByte = 7;
constexpr double kMetresPerCount = 1e-6;  // DBC: 0.001 mm
constexpr double kAmpsPerCount = 1e-3;    // DBC: 1 mA

// Id, DLC, checksum, then counter: the order a receiver can trust each field in.
DecodeStatus open_frame(std::uint32_t id, std::span<const std::uint8_t> data,
                        std::uint32_t expected_id, RollingCounterCheck* counter) {
  if (id != expected_id) return DecodeStatus::kWrongId;
  if (data.size() != kFrameLength) return DecodeStatus::kWrongDlc;
  if (crc8_sae_j1850(data.first(kChecksumByte)) != data[kChecksumByte]) {
    return DecodeStatus::kBadChecksum;
  }
  const auto rolling = static_cast<std::uint8_t>(data[kCounterByte] & 0x0F);
  return counter != nullptr ? counter->accept(rolling) : DecodeStatus::kOk;
}

void seal(Frame& f, std::uint8_t counter) {
  f.data[kCounterByte] = static_cast<std::uint8_t>(counter & 0x0F);
  f.data[kChecksumByte] = crc8_sae_j1850(std::span(f.data).first(kChecksumByte));
}

template <typename Int>
Int read_le(std::span<const std::uint8_t> data) {
  using U = std::make_unsigned_t<Int>;
  U u = 0;
  for (std::size_t i = 0; i < sizeof(Int); ++i) u = static_cast<U>(u | U(data[i]) << (8 * i));
  return static_cast<Int>(u);
}

template <typename Int>
EncodeStatus write_le(double si, double unit, Frame& f) {
  if (!std::isfinite(si)) return EncodeStatus::kNotFinite;
  const double raw = std::round(si / unit);
  if (raw < std::numeric_limits<Int>::min() || raw > std::numeric_limits<Int>::max()) {
    return EncodeStatus::kOutOfRange;
  }
  using U = std::make_unsigned_t<Int>;
  const auto u = static_cast<U>(static_cast<Int>(raw));
  for (std::size_t i = 0; i < sizeof(Int); ++i) f.data[i] = static_cast<std::uint8_t>(u >> (8 * i));
  return EncodeStatus::kOk;
}

// The command and feedback frames share one layout: int16 mA in bytes 0-1, a flag in byte 2.
struct CurrentLayout {
  double amps;
  bool flag;
  std::uint8_t counter;
};

Decoded<CurrentLayout> decode_current(std::uint32_t id, std::span<const std::uint8_t> data,
                                      std::uint32_t expected_id, RollingCounterCheck* counter) {
  const DecodeStatus status = open_frame(id, data, expected_id, counter);
  if (!carries_values(status)) return {status, {}};
  return {status,
          {read_le<std::int16_t>(data) * kAmpsPerCount, (data[kFlagByte] & 1) != 0,
           static_cast<std::uint8_t>(data[kCounterByte] & 0x0F)}};
}

Encoded encode_current(std::uint32_t id, const CurrentLayout& c) {
  Encoded out;
  out.frame.id = id;
  out.status = write_le<std::int16_t>(c.amps, kAmpsPerCount, out.frame);
  out.frame.data[kFlagByte] = c.flag ? 1 : 0;
  seal(out.frame, c.counter);
  return out;
}

}  // namespace

std::uint8_t crc8_sae_j1850(std::span<const std::uint8_t> bytes) {
  std::uint8_t crc = 0xFF;
  for (const std::uint8_t b : bytes) {
    crc ^= b;
    for (int bit = 0; bit < 8; ++bit) {
      crc = (crc & 0x80) != 0 ? static_cast<std::uint8_t>((crc << 1) ^ 0x1D)
                              : static_cast<std::uint8_t>(crc << 1);
    }
  }
  return static_cast<std::uint8_t>(crc ^ 0xFF);
}

std::string_view to_string(DecodeStatus s) {
  switch (s) {
    case DecodeStatus::kOk: return "ok";
    case DecodeStatus::kWrongId: return "wrong id";
    case DecodeStatus::kWrongDlc: return "wrong DLC";
    case DecodeStatus::kBadChecksum: return "bad checksum";
    case DecodeStatus::kRepeatedCounter: return "repeated counter";
    case DecodeStatus::kOutOfSequence: return "counter out of sequence";
  }
  return "unknown";
}

DecodeStatus RollingCounterCheck::accept(std::uint8_t counter) {
  counter &= 0x0F;
  const bool first = !has_last_;
  const std::uint8_t expected = static_cast<std::uint8_t>((last_ + 1) & 0x0F);
  if (!first && counter == last_) return DecodeStatus::kRepeatedCounter;
  has_last_ = true;
  last_ = counter;
  return first || counter == expected ? DecodeStatus::kOk : DecodeStatus::kOutOfSequence;
}

Decoded<LvdtFrame> decode_lvdt(std::uint32_t id, std::span<const std::uint8_t> data,
                               std::uint32_t expected_id, RollingCounterCheck* counter) {
  const DecodeStatus status = open_frame(id, data, expected_id, counter);
  if (!carries_values(status)) return {status, {}};
  return {status,
          {read_le<std::int32_t>(data) * kMetresPerCount, (data[kLvdtFlagByte] & 1) != 0,
           static_cast<std::uint8_t>(data[kCounterByte] & 0x0F)}};
}

Decoded<CurrentCommandFrame> decode_command(std::uint32_t id, std::span<const std::uint8_t> data,
                                            std::uint32_t expected_id,
                                            RollingCounterCheck* counter) {
  const auto d = decode_current(id, data, expected_id, counter);
  return {d.status, {d.value.amps, d.value.flag, d.value.counter}};
}

Decoded<CurrentFeedbackFrame> decode_feedback(std::uint32_t id, std::span<const std::uint8_t> data,
                                              std::uint32_t expected_id,
                                              RollingCounterCheck* counter) {
  const auto d = decode_current(id, data, expected_id, counter);
  return {d.status, {d.value.amps, d.value.flag, d.value.counter}};
}

Encoded encode_lvdt(std::uint32_t id, const LvdtFrame& f) {
  Encoded out;
  out.frame.id = id;
  out.status = write_le<std::int32_t>(f.displacement, kMetresPerCount, out.frame);
  out.frame.data[kLvdtFlagByte] = f.sensor_fault ? 1 : 0;
  seal(out.frame, f.counter);
  return out;
}

Encoded encode_command(std::uint32_t id, const CurrentCommandFrame& f) {
  return encode_current(id, {f.setpoint, f.enable, f.counter});
}

Encoded encode_feedback(std::uint32_t id, const CurrentFeedbackFrame& f) {
  return encode_current(id, {f.measured, f.driver_fault, f.counter});
}

}  // namespace mrd::hal::can
