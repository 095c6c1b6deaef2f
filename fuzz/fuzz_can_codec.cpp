// libFuzzer target: the CAN frame decoder (hal/can/can_codec), rolling counter and CRC-8
// included. The input is a stream of frames as a receiver would see them: per frame one
// header byte (bits 0-1: LVDT, command, feedback or a 4-byte force frame decoder, bit 7 then picking
// Load_Cell over Force_Demand; bits 2-5: DLC 0-15; bit 6: a
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

// Decodes one frame with `decode` (as if from a foreign id when `foreign`) and checks what a
// frame that carries values must satisfy.
template <typename Decode, typename Encode, typename Value>
void check_frame(Decode decode, Encode encode, std::uint32_t id, RollingCounterCheck& counter,
                 std::span<const std::uint8_t> payload, bool foreign, std::size_t value_bytes,
                 std::size_t flag_byte, double Value::*signal) {
  const auto d = decode(foreign ? 0x7FF : id, payload, id, &counter);
  if (foreign != (d.status == DecodeStatus::kWrongId)) std::abort();
  if (!carries_values(d.status)) return;
  check_sealed(payload);
  if (!std::isfinite(d.value.*signal)) std::abort();
  check_round_trip(encode(id, d.value), payload, value_bytes, flag_byte, d.value);
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  RollingCounterCheck lvdt_counter;
  RollingCounterCheck command_counter;
  RollingCounterCheck feedback_counter;
  RollingCounterCheck demand_counter;
  RollingCounterCheck load_cell_counter;
  std::span<const std::uint8_t> rest(data, size);
  while (!rest.empty()) {
    const std::uint8_t header = rest[0];
    rest = rest.subspan(1);
    const std::size_t dlc = std::min<std::size_t>((header >> 2) & 0x0F, rest.size());
    const auto payload = rest.first(dlc);
    rest = rest.subspan(dlc);
    const bool foreign = (header & 0x40) != 0;
    switch (header & 0x03) {
      case 0:
        check_frame(decode_lvdt, encode_lvdt, kDefaultLvdtId, lvdt_counter, payload, foreign, 4, 4,
                    &LvdtFrame::displacement);
        break;
      case 1:
        check_frame(decode_command, encode_command, kDefaultCommandId, command_counter, payload,
                    foreign, 2, 2, &CurrentCommandFrame::setpoint);
        break;
      case 2:
        check_frame(decode_feedback, encode_feedback, kDefaultFeedbackId, feedback_counter, payload,
                    foreign, 2, 2, &CurrentFeedbackFrame::measured);
        break;
      default:
        // Bit 7 picks the load cell's frame among the 4-byte force frames (the corpus's old
        // inputs keep their meaning: the demand).
        if ((header & 0x80) != 0) {
          check_frame(decode_load_cell, encode_load_cell, kDefaultLoadCellId, load_cell_counter, payload, foreign, 4,
                      4, &LoadCellFrame::force);
        } else {
          check_frame(decode_demand, encode_demand, kDefaultDemandId, demand_counter, payload, foreign, 4, 4,
                      &ForceDemandFrame::demand);
        }
        break;
    }
  }
  return 0;
}
