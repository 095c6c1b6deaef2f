// libFuzzer target: the Modbus register decoding (hal/modbus/register_codec). The input is one
// header byte (type, word order, byte order, and whether to take scale and offset from the
// next 16 bytes as raw doubles or use 1 and 0), then the register words as received, in any
// number. Bad formats and wrong word counts must be reported as such, a decoded value must be
// finite, and with scale 1 and offset 0 encoding it again must give back the same value (and,
// for integer registers, the same words).
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <cstring>
#include <vector>

#include "hal/modbus/register_codec.hpp"

namespace {

using namespace mrd::hal::modbus;

double take_double(const std::uint8_t*& data, std::size_t& size) {
  double value = 0.0;
  if (size < sizeof value) return value;
  std::memcpy(&value, data, sizeof value);
  data += sizeof value;
  size -= sizeof value;
  return value;
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  if (size == 0) return 0;
  const std::uint8_t header = data[0];
  ++data;
  --size;
  RegisterFormat format;
  format.type = static_cast<RegisterType>((header & 0x07) % 5);
  format.word_order = (header & 0x08) != 0 ? WordOrder::kLowFirst : WordOrder::kHighFirst;
  format.byte_order = (header & 0x10) != 0 ? ByteOrder::kSwapped : ByteOrder::kNormal;
  const bool identity = (header & 0x20) == 0;
  if (!identity) {
    format.scale = take_double(data, size);
    format.offset = take_double(data, size);
  }
  std::vector<std::uint16_t> words(size / 2);
  if (!words.empty()) std::memcpy(words.data(), data, words.size() * 2);

  const DecodeResult decoded = decode_register(words, format);
  const bool format_ok = std::isfinite(format.scale) && format.scale != 0.0 && std::isfinite(format.offset);
  if (format_ok != format.validate().ok()) std::abort();
  if (!format_ok) {
    if (decoded.status != CodecStatus::kBadFormat) std::abort();
    return 0;
  }
  if (words.size() != word_count(format.type)) {
    if (decoded.status != CodecStatus::kWrongWordCount) std::abort();
    return 0;
  }
  if (decoded.status != CodecStatus::kOk) {
    // Only a float register (NaN/inf) or a scale that overflows may give a non-finite value.
    if (decoded.status != CodecStatus::kNotFinite) std::abort();
    return 0;
  }
  if (!std::isfinite(decoded.value)) std::abort();
  if (identity) {
    const EncodeResult again = encode_register(decoded.value, format);
    if (again.status != CodecStatus::kOk || again.count != words.size()) std::abort();
    const DecodeResult back = decode_register(again.view(), format);
    if (back.status != CodecStatus::kOk || back.value != decoded.value) std::abort();
    // Integers have one encoding per value; a float's -0 decodes to 0 (the offset is added)
    // and comes back as +0, the same value in other bits.
    if (format.type != RegisterType::kFloat32) {
      for (std::size_t i = 0; i < words.size(); ++i) {
        if (again.words[i] != words[i]) std::abort();
      }
    }
  }
  return 0;
}
