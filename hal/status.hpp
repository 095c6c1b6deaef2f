#pragma once

#include <cerrno>
#include <cstdint>
#include <cstring>
#include <string>
#include <string_view>

namespace mrd::hal {

// What a hot-path HAL call reports instead of throwing.
enum class IoStatus : std::uint8_t {
  kOk,
  kNotConnected,     // the back end has no link yet, or is reconnecting
  kInvalidArgument,  // the value cannot be represented on the wire (NaN, out of the raw range)
  kTxInhibited,      // the back end holds transmission back by policy (CAN bus-off hold-off)
  kIoError,          // the system call or library call failed
};

[[nodiscard]] constexpr std::string_view to_string(IoStatus s) {
  switch (s) {
    case IoStatus::kOk: return "ok";
    case IoStatus::kNotConnected: return "not connected";
    case IoStatus::kInvalidArgument: return "invalid argument";
    case IoStatus::kTxInhibited: return "transmit inhibited";
    case IoStatus::kIoError: return "I/O error";
  }
  return "unknown";
}

// What a back end's start() reports: start-up may allocate and explain itself in words.
struct StartResult {
  bool ok = true;
  std::string error;  // one line per problem when !ok

  static StartResult success() { return {}; }
  static StartResult failure(std::string why) { return {false, std::move(why)}; }
};

// `what` and the reason errno gives, for a system call that just failed (start-up only).
inline std::string errno_text(const std::string& what) { return what + ": " + std::strerror(errno); }

}  // namespace mrd::hal
