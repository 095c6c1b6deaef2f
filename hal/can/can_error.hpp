#pragma once

#include <linux/can.h>
#include <linux/can/error.h>

#include <cstdint>

namespace mrd::hal::can {

// What a SocketCAN error frame (CAN_ERR_FLAG set, see <linux/can/error.h>) says, reduced to
// the conditions our bus-off policy and counters care about. Pure: no socket needed.
enum CanErrorBit : std::uint16_t {
  kErrBusOff = 1u << 0,
  kErrRestarted = 1u << 1,        // the controller left bus-off (restart-ms or a manual restart)
  kErrPassive = 1u << 2,          // RX or TX error-passive
  kErrWarning = 1u << 3,          // RX or TX error-warning level
  kErrBackToActive = 1u << 4,     // recovered to error-active
  kErrOverflow = 1u << 5,         // controller RX/TX buffer overflow: frames were lost
  kErrTxTimeout = 1u << 6,
  kErrNoAck = 1u << 7,            // nobody acknowledged our frame: alone on the bus, or wiring
  kErrProtocol = 1u << 8,         // protocol violation (bit, form, stuff error)
  kErrTransceiver = 1u << 9,
  kErrBusError = 1u << 10,
  kErrLostArbitration = 1u << 11,
};

struct CanErrorEvent {
  std::uint16_t bits = 0;
  [[nodiscard]] bool has(CanErrorBit b) const { return (bits & b) != 0; }
  [[nodiscard]] bool any() const { return bits != 0; }
};

// An empty event for frames that are not error frames.
[[nodiscard]] CanErrorEvent classify_error_frame(const can_frame& frame);

// The classes the back end subscribes to with CAN_RAW_ERR_FILTER. Bus errors are left out on
// purpose: the kernel warns they can flood the socket on a broken bus, and the protocol,
// controller and bus-off classes already tell us what we act on.
inline constexpr can_err_mask_t kSubscribedErrors = CAN_ERR_TX_TIMEOUT | CAN_ERR_CRTL |
                                                    CAN_ERR_PROT | CAN_ERR_TRX | CAN_ERR_ACK |
                                                    CAN_ERR_BUSOFF | CAN_ERR_RESTARTED;

}  // namespace mrd::hal::can
