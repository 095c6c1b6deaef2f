#include "hal/can/can_error.hpp"

#include <gtest/gtest.h>
#include <linux/can/error.h>

#include "hal/can/bus_off_policy.hpp"

namespace {

using namespace std::chrono_literals;
using namespace mrd::hal::can;
using mrd::hal::Timestamp;

can_frame error_frame(canid_t classes, std::uint8_t controller = 0) {
  can_frame f{};
  f.can_id = CAN_ERR_FLAG | classes;
  f.len = CAN_ERR_DLC;
  f.data[1] = controller;
  return f;
}

TEST(CanErrorFrame, DataFramesAreNotErrors) {
  can_frame f{};
  f.can_id = CAN_ERR_BUSOFF;  // the class bit alone, without CAN_ERR_FLAG, means nothing
  f.len = 8;
  EXPECT_FALSE(classify_error_frame(f).any());
}

TEST(CanErrorFrame, ClassifiesBusOffRestartAndControllerStates) {
  EXPECT_TRUE(classify_error_frame(error_frame(CAN_ERR_BUSOFF)).has(kErrBusOff));
  EXPECT_TRUE(classify_error_frame(error_frame(CAN_ERR_RESTARTED)).has(kErrRestarted));

  const auto passive = classify_error_frame(error_frame(CAN_ERR_CRTL, CAN_ERR_CRTL_TX_PASSIVE));
  EXPECT_TRUE(passive.has(kErrPassive));
  EXPECT_FALSE(passive.has(kErrBusOff));
  EXPECT_TRUE(classify_error_frame(error_frame(CAN_ERR_CRTL, CAN_ERR_CRTL_RX_WARNING))
                  .has(kErrWarning));
  EXPECT_TRUE(classify_error_frame(error_frame(CAN_ERR_CRTL, CAN_ERR_CRTL_RX_OVERFLOW))
                  .has(kErrOverflow));
  EXPECT_TRUE(classify_error_frame(error_frame(CAN_ERR_CRTL, CAN_ERR_CRTL_ACTIVE))
                  .has(kErrBackToActive));

  const auto several = classify_error_frame(
      error_frame(CAN_ERR_ACK | CAN_ERR_PROT | CAN_ERR_TX_TIMEOUT | CAN_ERR_BUSOFF));
  EXPECT_TRUE(several.has(kErrNoAck));
  EXPECT_TRUE(several.has(kErrProtocol));
  EXPECT_TRUE(several.has(kErrTxTimeout));
  EXPECT_TRUE(several.has(kErrBusOff));
}

TEST(CanErrorFrame, ShortControllerFrameDoesNotReadPastItsLength) {
  can_frame f = error_frame(CAN_ERR_CRTL, CAN_ERR_CRTL_TX_PASSIVE);
  f.len = 1;  // malformed: the controller byte is missing
  const auto e = classify_error_frame(f);
  EXPECT_FALSE(e.has(kErrPassive));
}

TEST(CanErrorFrame, SubscriptionCoversWhatThePolicyNeeds) {
  EXPECT_NE(kSubscribedErrors & CAN_ERR_BUSOFF, 0u);
  EXPECT_NE(kSubscribedErrors & CAN_ERR_RESTARTED, 0u);
  EXPECT_NE(kSubscribedErrors & CAN_ERR_CRTL, 0u);
  EXPECT_EQ(kSubscribedErrors & CAN_ERR_BUSERROR, 0u);  // may flood
}

class BusOffPolicyTest : public ::testing::Test {
 protected:
  BusOffPolicy policy{100ms};
  CanErrorEvent bus_off = classify_error_frame(error_frame(CAN_ERR_BUSOFF));
  CanErrorEvent restarted = classify_error_frame(error_frame(CAN_ERR_RESTARTED));
  CanErrorEvent passive = classify_error_frame(error_frame(CAN_ERR_CRTL, CAN_ERR_CRTL_TX_PASSIVE));
};

TEST_F(BusOffPolicyTest, StopsTransmittingUntilRestartPlusHoldOff) {
  Timestamp t{1s};
  EXPECT_TRUE(policy.tx_allowed(t));
  EXPECT_EQ(policy.state(t), BusOffPolicy::State::kActive);

  policy.on_error(bus_off, t);
  EXPECT_FALSE(policy.tx_allowed(t));
  EXPECT_EQ(policy.state(t + 1h), BusOffPolicy::State::kBusOff);  // no restart, no transmit
  EXPECT_EQ(policy.bus_off_events(), 1u);

  t += 20ms;
  policy.on_error(restarted, t);
  EXPECT_EQ(policy.state(t), BusOffPolicy::State::kHoldOff);
  EXPECT_FALSE(policy.tx_allowed(t + 99ms));
  EXPECT_TRUE(policy.tx_allowed(t + 100ms));
  EXPECT_EQ(policy.state(t + 100ms), BusOffPolicy::State::kActive);
}

TEST_F(BusOffPolicyTest, AGoodFrameAlsoProvesTheControllerIsBack) {
  const Timestamp t{5s};
  policy.on_error(bus_off, t);
  policy.on_error(passive, t + 1ms);  // other errors do not end bus-off
  EXPECT_EQ(policy.state(t + 1s), BusOffPolicy::State::kBusOff);
  policy.on_good_frame(t + 2s);
  EXPECT_EQ(policy.state(t + 2s), BusOffPolicy::State::kHoldOff);
  EXPECT_TRUE(policy.tx_allowed(t + 2s + 100ms));
}

TEST_F(BusOffPolicyTest, BusOffDuringHoldOffStartsOverAndIsCountedOncePerEpisode) {
  const Timestamp t{0s};
  policy.on_error(bus_off, t);
  policy.on_error(bus_off, t + 1ms);  // the same episode reported twice
  EXPECT_EQ(policy.bus_off_events(), 1u);
  policy.on_error(restarted, t + 10ms);
  policy.on_error(bus_off, t + 50ms);
  EXPECT_EQ(policy.bus_off_events(), 2u);
  EXPECT_FALSE(policy.tx_allowed(t + 1h));
  EXPECT_EQ(policy.tx_allowed_from(), Timestamp::max());
}

TEST_F(BusOffPolicyTest, RestartWithoutBusOffChangesNothing) {
  policy.on_error(restarted, Timestamp{1s});
  policy.on_good_frame(Timestamp{1s});
  EXPECT_TRUE(policy.tx_allowed(Timestamp{1s}));
  EXPECT_EQ(policy.bus_off_events(), 0u);
}

}  // namespace
