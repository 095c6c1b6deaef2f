// libFuzzer target: the CAN frame decoder (hal/can/can_codec), rolling counter and CRC-8
// included. The input is a stream of frames as a receiver would see them: per frame one
// header byte (bits 0-1: LVDT, command or feedback decoder; bits 2-5: DLC 0-15; bit 6: a
// foreign id) and then DLC payload bytes. Each decoder keeps its own counter check across the
// stream. A frame that carries values must be 8 bytes with a good checksum, its values finite,
// and encoding them again must give back the same payload.
#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <span>

#include "hal/can/can_codec.hpp"

namespace {

using namespace mrd::hal::can;

void check_sealed(std::span<const std::uint8_t> data) {
  if (data.size() != kFrameLength) std::abort();
  if (crc8_sae_j1850(data.first(7)) != data[7]) std::abort();
}

// Re-encodes a decoded frame and compares it with the payload: values, flag bit, counter.
template <typename Value>
void check_round_trip(const Encoded& again, std::span<const std::uint8_t> data,
                      std::size_t value_bytes, std::size_t flag_byte, const Value& v) {
  if (again.status != EncodeStatus::kOk) std::abort();
  if (!std::equal(data.begin(), data.begin() + static_cast<std::ptrdiff_t>(value_bytes),
                  again.frame.data.begin())) {
    std::abort();
  }
  if ((again.frame.data[flag_byte] & 1) != (data[flag_byte] & 1)) std::abort();
  if (v.counter != (data[6] & 0x0F)) std::abort();
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  RollingCounterCheck lvdt_counter;
  RollingCounterCheck command_counter;
  RollingCounterCheck feedback_counter;
  std::span<const std::uint8_t> rest(data, size);
  while (!rest.empty()) {
    const std::uint8_t header = rest[0];
    rest = rest.subspan(1);
    const std::size_t dlc = std::min<std::size_t>((header >> 2) & 0x0F, rest.size());
    const auto payload = rest.first(dlc);
    rest = rest.subspan(dlc);
    const bool foreign = (header & 0x40) != 0;
    switch (header & 0x03) {
      case 0: {
        const auto d = decode_lvdt(foreign ? 0x7FF : kDefaultLvdtId, payload, kDefaultLvdtId,
                                   &lvdt_counter);
        if (foreign != (d.status == DecodeStatus::kWrongId)) std::abort();
        if (!carries_values(d.status)) break;
        check_sealed(payload);
        if (!std::isfinite(d.value.displacement)) std::abort();
        check_round_trip(encode_lvdt(kDefaultLvdtId, d.value), payload, 4, 4, d.value);
        break;
      }
      case 1: {
        const auto d = decode_command(foreign ? 0x7FF : kDefaultCommandId, payload,
                                      kDefaultCommandId, &command_counter);
        if (foreign != (d.status == DecodeStatus::kWrongId)) std::abort();
        if (!carries_values(d.status)) break;
        check_sealed(payload);
        if (!std::isfinite(d.value.setpoint)) std::abort();
        check_round_trip(encode_command(kDefaultCommandId, d.value), payload, 2, 2, d.value);
        break;
      }
      default: {
        const auto d = decode_feedback(foreign ? 0x7FF : kDefaultFeedbackId, payload,
                                       kDefaultFeedbackId, &feedback_counter);
        if (foreign != (d.status == DecodeStatus::kWrongId)) std::abort();
        if (!carries_values(d.status)) break;
        check_sealed(payload);
        if (!std::isfinite(d.value.measured)) std::abort();
        check_round_trip(encode_feedback(kDefaultFeedbackId, d.value), payload, 2, 2, d.value);
        break;
      }
    }
  }
  return 0;
}
