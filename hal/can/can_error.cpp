#include "hal/can/can_error.hpp"

namespace mrd::hal::can {

CanErrorEvent classify_error_frame(const can_frame& frame) {
  CanErrorEvent e;
  if ((frame.can_id & CAN_ERR_FLAG) == 0) return e;
  const canid_t cls = frame.can_id & CAN_ERR_MASK;
  const auto set = [&e](bool on, CanErrorBit bit) {
    if (on) e.bits = static_cast<std::uint16_t>(e.bits | bit);
  };
  set((cls & CAN_ERR_BUSOFF) != 0, kErrBusOff);
  set((cls & CAN_ERR_RESTARTED) != 0, kErrRestarted);
  set((cls & CAN_ERR_TX_TIMEOUT) != 0, kErrTxTimeout);
  set((cls & CAN_ERR_ACK) != 0, kErrNoAck);
  set((cls & CAN_ERR_PROT) != 0, kErrProtocol);
  set((cls & CAN_ERR_TRX) != 0, kErrTransceiver);
  set((cls & CAN_ERR_BUSERROR) != 0, kErrBusError);
  set((cls & CAN_ERR_LOSTARB) != 0, kErrLostArbitration);
  if ((cls & CAN_ERR_CRTL) != 0 && frame.len >= 2) {
    const std::uint8_t ctrl = frame.data[1];
    set((ctrl & (CAN_ERR_CRTL_RX_PASSIVE | CAN_ERR_CRTL_TX_PASSIVE)) != 0, kErrPassive);
    set((ctrl & (CAN_ERR_CRTL_RX_WARNING | CAN_ERR_CRTL_TX_WARNING)) != 0, kErrWarning);
    set((ctrl & (CAN_ERR_CRTL_RX_OVERFLOW | CAN_ERR_CRTL_TX_OVERFLOW)) != 0, kErrOverflow);
    set((ctrl & CAN_ERR_CRTL_ACTIVE) != 0, kErrBackToActive);
  }
  return e;
}

}  // namespace mrd::hal::can
