#include "hal/can/can_codec.hpp"

#include <cmath>
#include <limits>
#include <type_traits>

namespace mrd::hal::can {

namespace {

constexpr std::size_t kFlagByte = 2;  // current frames
constexpr std::size_t kLvdtFlagByte = 4;
constexpr std::size_t kCounterByte = 6;
constexpr std::size_t kChecksumByte = 7;
constexpr double kMetresPerCount = 1e-6;  // DBC: 0.001 mm
constexpr double kAmpsPerCount = 1e-3;    // DBC: 1 mA
constexpr double kNewtonsPerCount = 0.1;  // DBC: 0.1 N

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

// Every frame is {scaled integer in bytes 0.., a flag bit, the counter}; only the integer's
// width, its unit and the flag's byte differ. Out is LvdtFrame, CurrentCommandFrame or
// CurrentFeedbackFrame, ForceDemandFrame or LoadCellFrame, all {double, bool, counter}.
template <typename Int, typename Out>
Decoded<Out> decode_payload(std::uint32_t id, std::span<const std::uint8_t> data,
                            std::uint32_t expected_id, RollingCounterCheck* counter, double unit,
                            std::size_t flag_byte) {
  const DecodeStatus status = open_frame(id, data, expected_id, counter);
  if (!carries_values(status)) return {status, {}};
  return {status,
          {read_le<Int>(data) * unit, (data[flag_byte] & 1) != 0,
           static_cast<std::uint8_t>(data[kCounterByte] & 0x0F)}};
}

template <typename Int>
Encoded encode_payload(std::uint32_t id, double value, bool flag, std::uint8_t counter,
                       double unit, std::size_t flag_byte) {
  Encoded out;
  out.frame.id = id;
  out.status = write_le<Int>(value, unit, out.frame);
  out.frame.data[flag_byte] = flag ? 1 : 0;
  seal(out.frame, counter);
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
  return decode_payload<std::int32_t, LvdtFrame>(id, data, expected_id, counter, kMetresPerCount,
                                                 kLvdtFlagByte);
}

Decoded<CurrentCommandFrame> decode_command(std::uint32_t id, std::span<const std::uint8_t> data,
                                            std::uint32_t expected_id,
                                            RollingCounterCheck* counter) {
  return decode_payload<std::int16_t, CurrentCommandFrame>(id, data, expected_id, counter,
                                                           kAmpsPerCount, kFlagByte);
}

Decoded<CurrentFeedbackFrame> decode_feedback(std::uint32_t id, std::span<const std::uint8_t> data,
                                              std::uint32_t expected_id,
                                              RollingCounterCheck* counter) {
  return decode_payload<std::int16_t, CurrentFeedbackFrame>(id, data, expected_id, counter,
                                                            kAmpsPerCount, kFlagByte);
}

Decoded<ForceDemandFrame> decode_demand(std::uint32_t id, std::span<const std::uint8_t> data,
                                        std::uint32_t expected_id, RollingCounterCheck* counter) {
  return decode_payload<std::int32_t, ForceDemandFrame>(id, data, expected_id, counter, kNewtonsPerCount,
                                                        kLvdtFlagByte);
}

// Laid out as Force_Demand: a force at 0.1 N in bytes 0-3, the flag in byte 4.
Decoded<LoadCellFrame> decode_load_cell(std::uint32_t id, std::span<const std::uint8_t> data,
                                        std::uint32_t expected_id, RollingCounterCheck* counter) {
  return decode_payload<std::int32_t, LoadCellFrame>(id, data, expected_id, counter, kNewtonsPerCount,
                                                     kLvdtFlagByte);
}

Encoded encode_lvdt(std::uint32_t id, const LvdtFrame& f) {
  return encode_payload<std::int32_t>(id, f.displacement, f.sensor_fault, f.counter,
                                      kMetresPerCount, kLvdtFlagByte);
}

Encoded encode_command(std::uint32_t id, const CurrentCommandFrame& f) {
  return encode_payload<std::int16_t>(id, f.setpoint, f.enable, f.counter, kAmpsPerCount,
                                      kFlagByte);
}

Encoded encode_feedback(std::uint32_t id, const CurrentFeedbackFrame& f) {
  return encode_payload<std::int16_t>(id, f.measured, f.driver_fault, f.counter, kAmpsPerCount,
                                      kFlagByte);
}

Encoded encode_demand(std::uint32_t id, const ForceDemandFrame& f) {
  return encode_payload<std::int32_t>(id, f.demand, f.invalid, f.counter, kNewtonsPerCount, kLvdtFlagByte);
}

Encoded encode_load_cell(std::uint32_t id, const LoadCellFrame& f) {
  return encode_payload<std::int32_t>(id, f.force, f.invalid, f.counter, kNewtonsPerCount, kLvdtFlagByte);
}

}  // namespace mrd::hal::can
