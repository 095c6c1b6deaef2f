#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <span>
#include <string_view>

namespace mrd::hal::can {

// Pure encoding and decoding of the frames in hal/can/mrd.dbc. No sockets here, so the codec
// can be unit-tested and fuzzed on arbitrary bytes. Every frame: 8 bytes, little-endian
// signals, rolling counter in byte 6 bits 0-3, CRC-8 SAE J1850 of bytes 0-6 in byte 7.

inline constexpr std::uint32_t kDefaultLvdtId = 0x110;
inline constexpr std::uint32_t kDefaultCommandId = 0x210;
inline constexpr std::uint32_t kDefaultFeedbackId = 0x211;
inline constexpr std::uint32_t kDefaultDemandId = 0x120;  // force mode's demand
inline constexpr std::uint32_t kDefaultLoadCellId = 0x130;  // force mode's optional measured force
inline constexpr std::size_t kFrameLength = 8;

// CRC-8 SAE J1850: polynomial 0x1D, init 0xFF, no reflection, final XOR 0xFF.
[[nodiscard]] std::uint8_t crc8_sae_j1850(std::span<const std::uint8_t> bytes);

struct Frame {
  std::uint32_t id = 0;  // without the EFF/RTR/ERR flag bits
  std::array<std::uint8_t, kFrameLength> data{};
};

enum class DecodeStatus : std::uint8_t {
  kOk,
  kWrongId,
  kWrongDlc,
  kBadChecksum,
  kRepeatedCounter,  // same counter as the last good frame: stale or duplicated
  kOutOfSequence,    // counter jumped: frames were lost. The decoded values ARE valid.
};
[[nodiscard]] std::string_view to_string(DecodeStatus s);
// True when the decoded values may be used (kOk, or kOutOfSequence with a gap to flag).
[[nodiscard]] constexpr bool carries_values(DecodeStatus s) {
  return s == DecodeStatus::kOk || s == DecodeStatus::kOutOfSequence;
}

// The receiver's view of one sender's 4-bit rolling counter. The first frame is accepted.
class RollingCounterCheck {
 public:
  DecodeStatus accept(std::uint8_t counter);
  void reset() { has_last_ = false; }

 private:
  bool has_last_ = false;
  std::uint8_t last_ = 0;
};

struct LvdtFrame {
  double displacement = 0.0;  // m (the wire carries um)
  bool sensor_fault = false;
  std::uint8_t counter = 0;
};
struct CurrentCommandFrame {
  double setpoint = 0.0;  // A (the wire carries mA)
  bool enable = false;
  std::uint8_t counter = 0;
};
struct CurrentFeedbackFrame {
  double measured = 0.0;  // A (the wire carries mA)
  bool driver_fault = false;
  std::uint8_t counter = 0;
};

// Force mode: the force the outer controller demands (docs/FORCE-CONTROL.md).
struct ForceDemandFrame {
  double demand = 0.0;   // N (the wire carries 0.1 N)
  bool invalid = false;  // the outer controller says its demand is unusable
  std::uint8_t counter = 0;
};

// Force mode's optional load cell: the damper force it measures (docs/FORCE-CONTROL.md,
// "Load-cell feedback").
struct LoadCellFrame {
  double force = 0.0;    // N (the wire carries 0.1 N)
  bool invalid = false;  // the load cell's amplifier says its value is unusable
  std::uint8_t counter = 0;
};

template <typename T>
struct Decoded {
  DecodeStatus status = DecodeStatus::kOk;
  T value{};  // meaningful only when carries_values(status)
};

// `data` is the frame's payload as received (its size is the DLC). `counter` may be null to
// skip the sequence check.
[[nodiscard]] Decoded<LvdtFrame> decode_lvdt(std::uint32_t id, std::span<const std::uint8_t> data,
                                             std::uint32_t expected_id,
                                             RollingCounterCheck* counter);
[[nodiscard]] Decoded<CurrentCommandFrame> decode_command(std::uint32_t id,
                                                          std::span<const std::uint8_t> data,
                                                          std::uint32_t expected_id,
                                                          RollingCounterCheck* counter);
[[nodiscard]] Decoded<CurrentFeedbackFrame> decode_feedback(std::uint32_t id,
                                                            std::span<const std::uint8_t> data,
                                                            std::uint32_t expected_id,
                                                            RollingCounterCheck* counter);
[[nodiscard]] Decoded<ForceDemandFrame> decode_demand(std::uint32_t id, std::span<const std::uint8_t> data,
                                                      std::uint32_t expected_id, RollingCounterCheck* counter);
[[nodiscard]] Decoded<LoadCellFrame> decode_load_cell(std::uint32_t id, std::span<const std::uint8_t> data,
                                                      std::uint32_t expected_id, RollingCounterCheck* counter);

enum class EncodeStatus : std::uint8_t { kOk, kNotFinite, kOutOfRange };
struct Encoded {
  EncodeStatus status = EncodeStatus::kOk;
  Frame frame;
};
// Values are rounded to the wire's resolution; the counter is taken modulo 16.
[[nodiscard]] Encoded encode_lvdt(std::uint32_t id, const LvdtFrame& f);
[[nodiscard]] Encoded encode_command(std::uint32_t id, const CurrentCommandFrame& f);
[[nodiscard]] Encoded encode_feedback(std::uint32_t id, const CurrentFeedbackFrame& f);
[[nodiscard]] Encoded encode_demand(std::uint32_t id, const ForceDemandFrame& f);
[[nodiscard]] Encoded encode_load_cell(std::uint32_t id, const LoadCellFrame& f);

}  // namespace mrd::hal::can
